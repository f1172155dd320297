// Vertex normal weightings (methods/operators/vertex_normals.h) by name, and the options of single
// methods (EstimatorOptions: vertex_normals, quadric_constant, ball_factor) checked by
// make_estimator.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "methods/estimator.h"
#include "methods/operators/vertex_normals.h"
#include "methods/option_schema.h"

namespace curvbench {
namespace {

TEST(VertexNormals, NamesRoundTrip) {
  const OptionInfo& info = option_info("vertex-normals");
  for (VertexNormals w : {VertexNormals::method_default, VertexNormals::area, VertexNormals::angle,
                          VertexNormals::max}) {
    EstimatorOptions o, back;
    o.vertex_normals = w;
    set_option(back, "vertex-normals", option_text(o, info));
    EXPECT_EQ(back.vertex_normals, w);
  }
  EstimatorOptions o;
  set_option(o, "vertex-normals", "max");
  EXPECT_EQ(o.vertex_normals, VertexNormals::max);
  try {
    set_option(o, "vertex-normals", "Area ");
    ADD_FAILURE() << "expected UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("valid: default, area, angle, max"), std::string::npos)
        << e.what();
  }
}

// An option of one method given to another is an error naming the option, not ignored.
TEST(VertexNormals, SingleMethodOptionsOnOtherMethodsAreErrors) {
  const auto expect_error = [](const std::string& method, const EstimatorOptions& o,
                               const std::string& needle) {
    try {
      make_estimator(method, o);
      ADD_FAILURE() << "expected UsageError for " << method;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  EstimatorOptions normals;
  normals.vertex_normals = VertexNormals::angle;
  expect_error("lhf-2", normals, "vertex-normals applies to the discrete operators only");
  for (const char* op :
       {"meyer", "taubin", "rusinkiewicz", "quadric", "goldfeather", "normal-cycle", "icc"})
    EXPECT_EQ(make_estimator(op, normals)->options().vertex_normals, VertexNormals::angle) << op;
  EstimatorOptions constant;
  constant.quadric_constant = true;
  expect_error("meyer", constant, "quadric-constant applies to method 'quadric' only");
  EXPECT_TRUE(make_estimator("quadric", constant)->options().quadric_constant);
  EstimatorOptions rjj_only;  // the safeguard's condition test off: ring fits only
  rjj_only.qr_condition = false;
  expect_error("jet-3", rjj_only, "qr-condition applies to the fits of the weighted");
  expect_error("meyer", rjj_only, "qr-condition applies to the fits of the weighted");
  for (const char* fit : {"lhf-4", "lop-2", "lscm-4"})
    EXPECT_FALSE(make_estimator(fit, rjj_only)->options().qr_condition) << fit;
  EstimatorOptions ball;
  ball.ball_factor = 2.0;
  // The error names every method whose registry line declares a ball, whatever they are.
  std::string ball_sized;
  for (const MethodInfo& m : method_table())
    if (m.radius == NeighbourhoodSize::ball_factor) ball_sized += "'" + m.name + "'";
  ASSERT_NE(ball_sized.find("'icc'"), std::string::npos);
  try {
    make_estimator("jet-3", ball);
    ADD_FAILURE() << "expected UsageError for jet-3 with ball-factor";
  } catch (const UsageError& e) {
    std::string named, what = e.what();
    EXPECT_EQ(what.rfind("ball-factor applies to methods ", 0), 0u) << what;
    for (size_t at = what.find('\''); at != std::string::npos; at = what.find('\'', at + 1)) {
      const size_t end = what.find('\'', at + 1);
      const std::string name = what.substr(at, end - at + 1);
      if (name != "'jet'") named += name;
      at = end;
    }
    EXPECT_EQ(named, ball_sized) << what;
  }
  EXPECT_EQ(make_estimator("normal-cycle", ball)->options().ball_factor, 2.0);
  EXPECT_EQ(make_estimator("icc", ball)->options().ball_factor, 2.0);
}

}  // namespace
}  // namespace curvbench
