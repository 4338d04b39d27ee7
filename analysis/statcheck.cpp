#include "analysis/statcheck.hpp"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "analysis/analysis_error.hpp"
#include "analysis/distributions.hpp"

namespace tlab::analysis {

std::string_view pRelationSymbol(PRelation relation) {
  switch (relation) {
    case PRelation::Less: return "<";
    case PRelation::Equal: return "=";
    case PRelation::Greater: return ">";
    case PRelation::NotSignificant: return "ns";
  }
  return "=";
}

std::string_view statisticName(StatisticKind kind) {
  switch (kind) {
    case StatisticKind::T: return "t";
    case StatisticKind::F: return "F";
    case StatisticKind::ChiSquared: return "chi2";
  }
  return "t";
}

bool reportedPConsistent(const Interval& computed, PRelation relation, const ReportedValue& p, double alpha) {
  switch (relation) {
    case PRelation::Equal: return computed.intersects(p.interval());
    case PRelation::Less: return computed.lo < p.value;
    case PRelation::Greater: return computed.hi > p.value;
    case PRelation::NotSignificant: return computed.hi > alpha;
  }
  return false;
}

std::size_t StatcheckReport::inconsistencies() const {
  std::size_t n = 0;
  for (const auto& v : verdicts) n += v.consistent ? 0 : 1;
  return n;
}

std::size_t StatcheckReport::decisionErrors() const {
  std::size_t n = 0;
  for (const auto& v : verdicts) n += v.decisionError ? 1 : 0;
  return n;
}

namespace {

// Text with PDF-extraction variants mapped to ASCII, and the source line of every character.
struct NormalizedText {
  std::string text;
  std::vector<std::size_t> line;
};

NormalizedText normalize(std::string_view in) {
  struct Replacement {
    std::string_view from;
    std::string_view to;
  };
  // Longest first where one is a prefix of another.
  static constexpr Replacement replacements[] = {
      {"\xE2\x88\x92", "-"},      // U+2212 minus sign
      {"\xE2\x80\x93", "-"},      // U+2013 en dash
      {"\xE2\x80\x94", "-"},      // U+2014 em dash
      {"\xE2\x80\x90", "-"},      // U+2010 hyphen
      {"\xCF\x87", "chi"},        // U+03C7 χ
      {"\xCE\xA7", "chi"},        // U+03A7 Χ
      {"\xC2\xB2", "2"},          // U+00B2 ²
      {"\xC2\xA0", " "},          // no-break space
      {"\xE2\x80\x89", " "},      // thin space
      {"\xE2\x80\xAF", " "},      // narrow no-break space
      {"\xE2\x89\xA4", "<"},      // ≤ (statcheck treats ≤ as <)
      {"\xE2\x89\xA5", ">"},      // ≥
      {"&lt;", "<"},
      {"&gt;", ">"},
      {"\\chi", "chi"},
      {"\n", " "},
      {"\r", " "},
      {"\t", " "},
  };
  NormalizedText out;
  std::size_t line = 1;
  for (std::size_t i = 0; i < in.size();) {
    bool replaced = false;
    for (const auto& r : replacements) {
      if (in.substr(i, r.from.size()) == r.from) {
        out.text += r.to;
        out.line.insert(out.line.end(), r.to.size(), line);
        if (r.from == "\n") ++line;
        i += r.from.size();
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    out.text.push_back(in[i]);
    out.line.push_back(line);
    ++i;
  }
  return out;
}

// Numbers are matched unambiguously as `\d+(\.\d+)?|\.\d+` and optional separators between
// blanks as `\s*(?:[,;]\s*)?`: the looser `\d*\.?\d+` and `\s*[,;]?\s*` let std::regex's
// backtracking split a long run of digits or blanks every possible way (a 619-byte text of digits
// and blanks took over 10 s — found by the statcheck fuzzer).
const std::regex& apaPattern() {
  // (1) t(df)  (2,3) F(df1, df2)  (4) χ²(df[, N = n])  then "= value" then "[,;] p <op> value" or "ns".
  static const std::regex pattern(
      R"((?:\bt\s*\(\s*(\d+(?:\.\d+)?)\s*\))"
      R"(|\bF\s*\(\s*(\d+(?:\.\d+)?)\s*,\s*(\d+(?:\.\d+)?)\s*\))"
      R"(|(?:\bchi\s*(?:\^\s*)?(?:\{\s*)?2\s*\}?|\bchi-squared?|\bchi-square|\b[Xx]\s*(?:\^\s*)?2)\s*\(\s*(\d+(?:\.\d+)?)\s*(?:,\s*[Nn]\s*=\s*\d+\s*)?\)))"
      R"(\s*=\s*(-?\s*(?:\d+(?:\.\d+)?|\.\d+))\s*(?:[,;]\s*)?(?:\b[pP]\s*([<>=])\s*((?:\d+(?:\.\d+)?|\.\d+)(?:[eE]-?\d+)?)|\b(ns|n\.s\.)))");
  return pattern;
}

const std::regex& bareP() {
  static const std::regex pattern(R"(\b[pP]\s*[<>=]\s*(?:\d+(?:\.\d+)?|\.\d+))");
  return pattern;
}

const std::regex& oneTailedWording() {
  // statcheck matches a bare "directional"; in graphics papers that is mostly "directional light",
  // so it is only taken together with the word it qualifies.
  static const std::regex pattern(R"(one[- ]?tailed|one[- ]?sided|directional\s+(?:test|hypothes|predict))",
                                  std::regex::icase);
  return pattern;
}

Interval pRangeOf(const ApaResult& r) {
  const Interval s = r.statistic.interval();
  switch (r.kind) {
    case StatisticKind::T: {
      const Interval a = abs(s);
      return mapDecreasing(a, [&](double t) { return studentTPValue(t, r.df1, Alternative::TwoSided); });
    }
    case StatisticKind::F:
      return mapDecreasing(Interval{std::max(0.0, s.lo), s.hi},
                           [&](double f) { return fisherFUpperTail(f, r.df1, r.df2); });
    case StatisticKind::ChiSquared:
      return mapDecreasing(Interval{std::max(0.0, s.lo), s.hi},
                           [&](double x) { return chiSquaredUpperTail(x, r.df1); });
  }
  return {};
}

double pAt(const ApaResult& r, double value) {
  switch (r.kind) {
    case StatisticKind::T: return studentTPValue(value, r.df1, Alternative::TwoSided);
    case StatisticKind::F: return fisherFUpperTail(value, r.df1, r.df2);
    case StatisticKind::ChiSquared: return chiSquaredUpperTail(value, r.df1);
  }
  return std::nan("");
}

std::string fmt(double x) {
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}

}  // namespace

std::vector<ApaResult> extractApaResults(std::string_view text) {
  const NormalizedText norm = normalize(text);
  std::vector<ApaResult> results;
  for (auto it = std::sregex_iterator(norm.text.begin(), norm.text.end(), apaPattern());
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    ApaResult r;
    // A match whose numbers cannot stand for a test (df <= 0, a value beyond double's range) is
    // not a test result: it is skipped, like any other text (found by fuzz/statcheck_fuzzer).
    try {
      if (m[1].matched) {
        r.kind = StatisticKind::T;
        r.df1 = std::stod(m[1].str());
      } else if (m[2].matched) {
        r.kind = StatisticKind::F;
        r.df1 = std::stod(m[2].str());
        r.df2 = std::stod(m[3].str());
      } else {
        r.kind = StatisticKind::ChiSquared;
        r.df1 = std::stod(m[4].str());
      }
      r.statistic = ReportedValue::parse(m[5].str());
      if (m[8].matched) {
        r.pRelation = PRelation::NotSignificant;
      } else {
        const char op = m[6].str()[0];
        r.pRelation = op == '<' ? PRelation::Less : (op == '>' ? PRelation::Greater : PRelation::Equal);
        r.p = ReportedValue::parse(m[7].str());
      }
    } catch (const std::logic_error&) {  // std::out_of_range, std::invalid_argument from std::stod
      continue;
    }
    const bool dfValid = r.df1 > 0.0 && std::isfinite(r.df1) && (r.kind != StatisticKind::F || (r.df2 > 0.0 && std::isfinite(r.df2)));
    if (!dfValid || !std::isfinite(r.statistic.value)) continue;
    r.text = m[0].str();
    r.line = norm.line[static_cast<std::size_t>(m.position(0))];
    results.push_back(r);
  }
  return results;
}

StatcheckVerdict checkApaResult(const ApaResult& result, bool oneTailedInText, double alpha) {
  StatcheckVerdict v;
  v.result = result;
  v.pComputed = pAt(result, result.statistic.value);
  v.pRange = pRangeOf(result);
  if (result.pRelation == PRelation::Equal && result.p.value == 0.0) {
    v.consistent = false;
    v.note = "a p-value cannot be 0 (report p < .001)";
  } else {
    v.consistent = reportedPConsistent(v.pRange, result.pRelation, result.p, alpha);
  }
  if (!v.consistent && result.kind == StatisticKind::T && result.p.value > 0.0) {
    const Interval half{v.pRange.lo / 2, v.pRange.hi / 2};
    v.consistentIfOneTailed = reportedPConsistent(half, result.pRelation, result.p, alpha);
    if (v.consistentIfOneTailed) {
      if (oneTailedInText) {
        v.consistent = true;
        v.note = "consistent as a one-tailed test (the text mentions one-tailed/one-sided testing)";
      } else {
        v.note = "would be consistent if one-tailed, but the text never says one-tailed";
      }
    }
  }
  if (!v.consistent) {
    bool reportedSignificant = false;
    bool reportedNotSignificant = false;
    switch (result.pRelation) {
      case PRelation::Equal:
        reportedSignificant = result.p.value <= alpha;
        reportedNotSignificant = !reportedSignificant;
        break;
      case PRelation::Less: reportedSignificant = result.p.value <= alpha; break;
      case PRelation::Greater: reportedNotSignificant = result.p.value >= alpha; break;
      case PRelation::NotSignificant: reportedNotSignificant = true; break;
    }
    const bool computedSignificant = v.pRange.hi < alpha;
    const bool computedNotSignificant = v.pRange.lo >= alpha;
    v.decisionError = (reportedSignificant && computedNotSignificant) ||
                      (reportedNotSignificant && computedSignificant);
    if (v.note.empty())
      v.note = "recomputed p = " + fmt(v.pComputed) + " (range " + fmt(v.pRange.lo) + " to " + fmt(v.pRange.hi) +
               " over the rounding of the statistic)";
    if (v.decisionError) v.note += "; decision error at alpha = " + fmt(alpha);
  }
  return v;
}

StatcheckReport statcheck(std::string_view text, const std::string& source, double alpha) {
  StatcheckReport report;
  report.source = source;
  const NormalizedText norm = normalize(text);
  report.oneTailedInText = std::regex_search(norm.text, oneTailedWording());
  const std::vector<ApaResult> results = extractApaResults(text);
  for (const auto& r : results) report.verdicts.push_back(checkApaResult(r, report.oneTailedInText, alpha));
  const auto bare = static_cast<std::size_t>(
      std::distance(std::sregex_iterator(norm.text.begin(), norm.text.end(), bareP()), std::sregex_iterator()));
  std::size_t inResults = 0;
  for (const auto& r : results) inResults += r.pRelation == PRelation::NotSignificant ? 0 : 1;
  report.pValuesWithoutStatistic = bare >= inResults ? bare - inResults : 0;
  return report;
}

StatcheckReport statcheckFile(const std::string& path, double alpha) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw AnalysisError(path + ": cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return statcheck(buffer.str(), path, alpha);
}

}  // namespace tlab::analysis
