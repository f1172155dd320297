// Claims G1-G4: the paper's conclusions (§6), each a conjunction of earlier claims (all_of), one
// registry entry each (harness/claims/kit.h; docs/claims.md).
#include "harness/claims/kit.h"

namespace curvbench::claims {

std::vector<ClaimEntry> section6_claims() {
  auto all_of = [](std::string id, std::string title, std::string statement,
                   std::vector<std::string> ids) {
    ClaimEntry e;
    e.id = std::move(id);
    e.title = std::move(title);
    e.statement = std::move(statement);
    e.band = "conjunction of " + join(ids, ", ");
    e.all_of = std::move(ids);
    return e;
  };
  return {
      all_of("G1", "Robust polynomial fits converge for exact or O(h^3) data",
             "Polynomial fits with a robust solver converge for exact or O(h^3) data (B1-B2, D, "
             "E8). Convergence is not guaranteed, but curvatures remain meaningful (often about "
             "first order), for O(h^2) data (E3, E9).",
             {"B1", "B2", "D1", "D2", "D3", "D4", "D5", "D6", "E8", "E3", "E9"}),
      all_of("G2", "LSCM good for d <= 3 but not d = 4; LHF and LOP reach high-order rates",
             "Approximate conformal parameterization (LSCM) is good for d <= 3 but not for d = 4; "
             "LHF and LOP reach high-order rates (C2-C5, D4-D5).",
             {"C2", "C3", "C4", "C5", "D4", "D5"}),
      all_of("G3", "The choice of solver matters for accuracy and speed",
             "The choice of solver matters for accuracy and speed: Xu/SVD failures (B5, D3, E7); "
             "F4, F7.",
             {"B5", "D3", "E7", "F4", "F7"}),
      all_of("G4", "LOP with safeguard (= LHF) gives the best combination",
             "LOP with the normal-angle safeguard (= LHF) gives the best combination of "
             "simplicity, accuracy, efficiency and robustness (A5, B1-B2, D1, F1-F2).",
             {"A5", "B1", "B2", "D1", "F1", "F2"}),
  };
}

}  // namespace curvbench::claims
