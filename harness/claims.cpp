// The claims registry: the entries of every paper section in order (harness/claims_kit.h), their
// evaluation against a results folder and results/CLAIMS.md.
#include "harness/claims.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "harness/claims_kit.h"
#include "harness/readings.h"

namespace curvbench {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::reproduced:
      return "reproduced";
    case Verdict::not_reproduced:
      return "not reproduced";
    case Verdict::not_applicable:
      return "not applicable";
  }
  return "?";
}

namespace {

const std::vector<claims::ClaimEntry>& registry() {
  static const std::vector<claims::ClaimEntry> entries = [] {
    std::vector<claims::ClaimEntry> all;
    for (auto section :
         {claims::exact_claims, claims::section5_1_claims, claims::section5_2_claims,
          claims::section5_3_claims, claims::section5_4_claims, claims::section6_claims})
      for (auto& e : section()) all.push_back(std::move(e));
    return all;
  }();
  return entries;
}

const claims::ClaimEntry* find_entry(const std::string& id) {
  for (const auto& e : registry())
    if (e.id == id) return &e;
  return nullptr;
}

std::string escape_cell(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out;
}

}  // namespace

Band claim_band(const std::string& id, const std::string& name) {
  const claims::ClaimEntry* e = find_entry(id);
  if (!e) throw std::out_of_range("no claim " + id);
  const auto it = e->bands.find(name);
  if (it == e->bands.end()) throw std::out_of_range("claim " + id + " has no band " + name);
  return it->second;
}

namespace {

// Conjunction: not reproduced if any cited claim is not reproduced; reproduced if every cited
// claim is; otherwise (some cited claims lack data) not applicable. `verdict_of` picks the
// verdict (ours or the level-halving one) of a cited claim.
void evaluate_all_of(const claims::ClaimEntry& def, const std::vector<ClaimResult>& earlier,
                     Verdict ClaimResult::*verdict_of, Verdict& verdict, std::string& evidence) {
  int rep = 0, na = 0;
  std::vector<std::string> lines;
  for (const auto& id : def.all_of) {
    const auto it = std::find_if(earlier.begin(), earlier.end(),
                                 [&](const ClaimResult& x) { return x.id == id; });
    const Verdict v = it == earlier.end() ? Verdict::not_applicable : (*it).*verdict_of;
    rep += v == Verdict::reproduced;
    na += v == Verdict::not_applicable;
    lines.push_back(std::string(v == Verdict::reproduced       ? "[ok] "
                                : v == Verdict::not_applicable ? "[missing] "
                                                               : "[FAIL] ") +
                    id + ": " + to_string(v));
  }
  const int n = static_cast<int>(def.all_of.size());
  const int failed = n - rep - na;
  verdict = failed > 0 ? Verdict::not_reproduced
            : rep == n ? Verdict::reproduced
                       : Verdict::not_applicable;
  if (failed == 0 && na > 0 && rep > 0)
    lines.push_back("[info] partially evaluated: " + std::to_string(rep) + " of " +
                    std::to_string(n) + " cited claims reproduced, the rest lack data");
  evidence = claims::join(lines, "\n");
}

// The [ok]/[FAIL] lines of `b` whose outcome differs from the line at the same position among
// the [ok]/[FAIL] lines of `a` (both evaluations run the same checks in the same order); every
// [FAIL] line of `b` if the numbers of checks differ.
std::string differing_checks(const std::string& a, const std::string& b) {
  auto checks = [](const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("[ok]", 0) == 0 || line.rfind("[FAIL]", 0) == 0) out.push_back(line);
    return out;
  };
  const auto ca = checks(a), cb = checks(b);
  std::vector<std::string> out;
  for (size_t i = 0; i < cb.size(); ++i) {
    const bool fail_b = cb[i].rfind("[FAIL]", 0) == 0;
    if (ca.size() != cb.size() ? fail_b : fail_b != (ca[i].rfind("[FAIL]", 0) == 0))
      out.push_back(cb[i]);
  }
  return claims::join(out, "\n");
}

// Substitutes `by` for `family` in the checks for the lifetime of the object.
class FamilyScope {
 public:
  FamilyScope(const std::string& family, const std::string& by)
      : family_(family), saved_(claims::family(family)) {
    claims::set_substitute(family_, by);
  }
  ~FamilyScope() { claims::set_substitute(family_, saved_); }
  FamilyScope(const FamilyScope&) = delete;
  FamilyScope& operator=(const FamilyScope&) = delete;

 private:
  std::string family_, saved_;
};

// The "Why" line of a checked claim that is not reproduced: every diagnostic the registry can run
// from the same CSVs (the other rate formula; the same check on the other well-shaped tori), plus
// the entry's own measured cause.
std::string why_line(const claims::ClaimEntry& def, const claims::Data& data,
                     const ClaimResult& r) {
  std::vector<std::string> causes, tried;
  if (r.halving_verdict == Verdict::reproduced)
    causes.push_back(
        "the rate formula: with the paper's level-halving rate the claim is reproduced");
  else
    tried.push_back("the paper's level-halving rate (" + std::string(to_string(r.halving_verdict)) +
                    ")");
  if (r.evidence.find(claims::kWell) != std::string::npos) {
    std::vector<std::string> shapes;
    bool reproduced_elsewhere = false;
    for (const std::string family : {"torus-jittered", "torus-structured"}) {
      // Rates over the measured h (evaluate_claims' default).
      const FamilyScope scope(claims::kWell, family);
      claims::Check c;
      def.check(data, c);
      shapes.push_back(family + ": " + to_string(c.verdict()));
      reproduced_elsewhere = reproduced_elsewhere || c.verdict() == Verdict::reproduced;
    }
    const std::string text =
        "the same check with the well-shaped torus replaced by " + claims::join(shapes, ", ");
    if (reproduced_elsewhere)
      causes.push_back("the mesh shape: " + text);
    else
      tried.push_back(text);
  }
  // The entry's own diagnostic: a cause, or (text starting "tried ") one more thing tried.
  if (def.why) {
    const std::string cause = def.why(data);
    if (cause.rfind("tried ", 0) == 0)
      tried.push_back(cause.substr(6));
    else if (!cause.empty())
      causes.push_back(cause);
  }
  if (!causes.empty()) return claims::join(causes, "; ") + ".";
  return "no cause found; tried " + claims::join(tried, "; ") + ".";
}

// Sets the rate formula for the lifetime of the object.
class FormulaScope {
 public:
  explicit FormulaScope(claims::RateFormula f) : saved_(claims::rate_formula()) {
    claims::rate_formula() = f;
  }
  ~FormulaScope() { claims::rate_formula() = saved_; }
  FormulaScope(const FormulaScope&) = delete;
  FormulaScope& operator=(const FormulaScope&) = delete;

 private:
  claims::RateFormula saved_;
};

// The result of claim `id` in one alternative's results (nullptr if absent).
const ClaimResult* result_of(const std::vector<ClaimResult>& results, const std::string& id) {
  for (const auto& r : results)
    if (r.id == id) return &r;
  return nullptr;
}

// The alternatives under which claim r's evidence differs from the adopted readings' (the
// readings that touch the claim).
std::vector<std::pair<const ReadingResults*, const ClaimResult*>> touching(
    const ClaimResult& r, const std::vector<ReadingResults>& alternatives) {
  std::vector<std::pair<const ReadingResults*, const ClaimResult*>> out;
  for (const auto& alt : alternatives)
    if (const ClaimResult* x = result_of(alt.results, r.id); x && x->evidence != r.evidence)
      out.push_back({&alt, x});
  return out;
}

int reproduced_under_some_reading(const std::vector<ClaimResult>& results,
                                  const std::vector<ReadingResults>& alternatives) {
  int n = 0;
  for (const auto& r : results) {
    bool any = r.verdict == Verdict::reproduced;
    for (const auto& [alt, x] : touching(r, alternatives))
      any = any || x->verdict == Verdict::reproduced;
    n += any;
  }
  return n;
}

// The readings table: each alternative, what it does, and the claims whose verdict it changes.
std::string readings_markdown(const std::vector<ClaimResult>& results,
                              const std::vector<ReadingResults>& alternatives) {
  if (alternatives.empty()) return "";
  std::ostringstream md;
  md << "**Readings.** Where the paper leaves a choice open, curvbench adopts one reading and "
        "also runs the experiments under the alternatives (harness/readings.cpp; the arguments "
        "are in docs/claims.md, made without reference to the verdicts). Each claim's section "
        "lists its verdict under every alternative that changes its evidence.\n\n"
     << "| reading | alternative | what it does | claims touched | verdict changes |\n"
     << "|---|---|---|---|---|\n";
  for (const auto& alt : alternatives) {
    std::vector<std::string> touched, changed;
    for (const auto& r : results) {
      const ClaimResult* x = result_of(alt.results, r.id);
      if (!x || x->evidence == r.evidence) continue;
      touched.push_back(r.id);
      if (x->verdict != r.verdict) changed.push_back(r.id + " " + to_string(x->verdict));
    }
    md << "| " << alt.reading << " | " << alt.choice << " | " << escape_cell(alt.description)
       << " | " << (touched.empty() ? "none" : claims::join(touched, ", ")) << " | "
       << (changed.empty() ? "none" : claims::join(changed, ", ")) << " |\n";
  }
  md << "\n";
  return md.str();
}

// The Why line of a claim not reproduced, with the readings: a reading under which it is
// reproduced is a measured cause (the paper's choice, argued in docs/claims.md); readings that
// touch it without reproducing it join the list of what was tried.
std::string why_with_readings(const ClaimResult& r,
                              const std::vector<ReadingResults>& alternatives) {
  if (r.verdict != Verdict::not_reproduced) return r.why;
  std::vector<std::string> reproducing, tried;
  for (const auto& [alt, x] : touching(r, alternatives))
    (x->verdict == Verdict::reproduced ? reproducing : tried)
        .push_back(alt->reading + "=" + alt->choice);
  std::string why = r.why;
  const std::string none = "no cause found; tried ";
  if (!reproducing.empty()) {
    const std::string cause = "the reading of the paper: reproduced under " +
                              claims::join(reproducing, ", ") + " (docs/claims.md)";
    why = why.rfind(none, 0) == 0 ? cause + "; also tried " + why.substr(none.size())
                                  : cause + "; " + why;
  } else if (!tried.empty()) {
    if (!why.empty() && why.back() == '.') why.pop_back();
    why += "; the readings " + claims::join(tried, ", ") + " (not reproduced either).";
  }
  return why;
}

// A claim's verdict under each alternative reading that touches it.
std::string claim_sensitivity(const ClaimResult& r,
                              const std::vector<ReadingResults>& alternatives) {
  const auto t = touching(r, alternatives);
  if (t.empty()) return "";
  std::ostringstream md;
  md << "Sensitivity to the readings (docs/claims.md):\n\n| reading | verdict |\n|---|---|\n"
     << "| adopted | " << to_string(r.verdict) << " |\n";
  for (const auto& [alt, x] : t) {
    md << "| " << alt->reading << "=" << alt->choice << " | " << to_string(x->verdict);
    if (x->verdict == Verdict::not_reproduced) {
      // The checks that fail under the alternative.
      std::vector<std::string> lines;
      std::istringstream in(x->evidence);
      for (std::string line; std::getline(in, line);)
        if (line.rfind("[FAIL]", 0) == 0) lines.push_back(line);
      if (lines.size() > 3) lines.resize(3);
      if (!lines.empty()) md << ": " << escape_cell(claims::join(lines, "; "));
    }
    md << " |\n";
  }
  md << "\n";
  return md.str();
}

}  // namespace

std::vector<ClaimResult> evaluate_claims(const std::string& results_dir, const std::string& overlay,
                                         const FamilySubstitute& substitute) {
  const claims::Data data(results_dir, overlay);
  const FamilyScope swap(substitute.family, substitute.by);
  std::vector<ClaimResult> out;
  for (const auto& def : registry()) {
    ClaimResult r;
    r.id = def.id;
    r.statement = def.statement;
    r.band = def.band;
    if (def.check) {
      {
        const FormulaScope ours(claims::RateFormula::measured_h);
        claims::Check c;
        def.check(data, c);
        r.verdict = c.verdict();
        r.evidence = c.evidence();
      }
      if (def.original_check) {
        const FormulaScope ours(claims::RateFormula::measured_h);
        claims::Check c;
        def.original_check(data, c);
        r.original_band = def.original_band;
        r.reread_reason = def.reread_reason;
        r.original_verdict = c.verdict();
        r.original_evidence = c.evidence();
      }
      const FormulaScope paper(claims::RateFormula::level_halving);
      claims::Check c;
      def.check(data, c);
      r.halving_verdict = c.verdict();
      if (r.halving_verdict != r.verdict)
        r.halving_evidence = differing_checks(r.evidence, c.evidence());
    } else {
      evaluate_all_of(def, out, &ClaimResult::verdict, r.verdict, r.evidence);
      std::string halving;
      evaluate_all_of(def, out, &ClaimResult::halving_verdict, r.halving_verdict, halving);
      if (r.halving_verdict != r.verdict)
        r.halving_evidence = differing_checks(r.evidence, halving);
    }
    if (r.verdict == Verdict::not_reproduced) {
      if (def.check) {
        r.why = why_line(def, data, r);
      } else {
        std::vector<std::string> misses;
        for (const auto& id : def.all_of)
          for (const auto& x : out)
            if (x.id == id && x.verdict == Verdict::not_reproduced) misses.push_back(id);
        r.why = "cites claims not reproduced: " + claims::join(misses, ", ") +
                " (see their Why lines).";
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ReadingResults> evaluate_readings(const std::string& results_dir) {
  std::vector<ReadingResults> out;
  for (const Reading& reading : readings())
    for (size_t i = 1; i < reading.choices.size(); ++i) {
      const ReadingChoice& choice = reading.choices[i];
      const std::string folder = reading_folder(results_dir, reading, choice);
      std::error_code ec;
      if (!std::filesystem::is_directory(folder, ec)) continue;
      out.push_back({reading.id, choice.name, choice.description,
                     evaluate_claims(results_dir, folder, choice.substitute)});
    }
  return out;
}

std::string claims_markdown(const std::vector<ClaimResult>& results, const std::string& header_line,
                            const std::vector<ReadingResults>& alternatives) {
  int rep = 0, notrep = 0, na = 0;
  for (const auto& r : results) {
    rep += r.verdict == Verdict::reproduced;
    notrep += r.verdict == Verdict::not_reproduced;
    na += r.verdict == Verdict::not_applicable;
  }
  std::ostringstream md;
  md << "# Paper claims: reproduction check\n\n"
     << header_line << "\n\n"
     << "Checks the claims of Wang, Jiao et al., CAGD 2009 listed in docs/claims.md against "
        "the CSVs in this folder (harness/claims_*.cpp). Each claim has a numeric band fixed in "
        "advance. A claim outside its band is reported as *not reproduced*, and the methods are "
        "not tuned to fit it. A claim whose data is missing, or whose run used a different "
        "setup, is *not applicable*. Rates are log(e_first/e_last)/log(h_first/h_last) over the "
        "levels present, with the measured mean edge length h; each rate line also gives the "
        "paper's level-halving rate (1/(L-1)) log2(e_first/e_last), every claim is evaluated "
        "with both, and a claim whose verdict differs is flagged. \"levels 1-4: a, b, c, d\" "
        "lists a value per mesh level. "
        "Evidence lines are tagged [ok], [FAIL], [missing] or [info].\n\n"
     << "**Summary:** " << rep << " reproduced, " << notrep << " not reproduced, " << na
     << " not applicable (" << results.size() << " claims)"
     << (alternatives.empty()
             ? std::string(".")
             : " under the adopted readings; " +
                   std::to_string(reproduced_under_some_reading(results, alternatives)) +
                   " reproduced under some fair reading.")
     << "\n\n"
     << readings_markdown(results, alternatives)
     << "| claim | verdict | subject |\n|---|---|---|\n";
  for (const auto& r : results) {
    const claims::ClaimEntry* def = find_entry(r.id);
    md << "| " << r.id << " | " << to_string(r.verdict)
       << (r.halving_verdict != r.verdict
               ? std::string(" (level-halving rate: ") + to_string(r.halving_verdict) + ")"
               : std::string())
       << (r.original_band.empty() || r.original_verdict == r.verdict
               ? std::string()
               : std::string(" (band fixed in advance: ") + to_string(r.original_verdict) + ")")
       << " | " << escape_cell(def ? def->title : r.statement) << " |\n";
  }
  md << "\n";
  for (const auto& r : results) {
    const claims::ClaimEntry* def = find_entry(r.id);
    md << "## " << r.id << ". " << (def ? def->title : "") << "\n\n"
       << "**Verdict: " << to_string(r.verdict) << "**\n\n";
    if (!r.why.empty()) md << "**Why:** " << why_with_readings(r, alternatives) << "\n\n";
    md << "- Paper: " << r.statement << "\n"
       << "- Band: " << r.band << "\n\n";
    if (!r.original_band.empty()) {
      md << "**Band re-read.** The band fixed in advance was: " << r.original_band
         << ". Verdict under it: *" << to_string(r.original_verdict) << "*. Re-read because "
         << r.reread_reason << " Its checks:\n\n";
      std::istringstream lines(r.original_evidence);
      for (std::string line; std::getline(lines, line);) md << "- " << line << "\n";
      md << "\n";
    }
    md << claim_sensitivity(r, alternatives);
    if (r.halving_verdict != r.verdict) {
      md << "**Rate formula: the verdict differs.** With the paper's level-halving rate "
            "(1/(L-1)) log2(e_1/e_L) instead of ours over the measured mean edge length, this "
            "claim is *"
         << to_string(r.halving_verdict) << "*. The checks that change:\n\n";
      std::istringstream lines(r.halving_evidence);
      for (std::string line; std::getline(lines, line);) md << "- " << line << "\n";
      md << "\n";
    }
    md << "Evidence:\n\n";
    std::istringstream lines(r.evidence);
    std::string line;
    bool any = false;
    while (std::getline(lines, line)) {
      md << "- " << line << "\n";
      any = true;
    }
    if (!any) md << "- (none)\n";
    md << "\n";
  }
  return md.str();
}

}  // namespace curvbench
