#include "analysis/statcheck_scanner.hpp"

#include <re2/re2.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace tlab::analysis {

NormalizedText normalizeForStatcheck(std::string_view in) {
  struct Replacement {
    std::string_view from;
    std::string_view to;
  };
  static constexpr Replacement replacements[] = {
      {"\xE2\x88\x92", "-"},  // U+2212 minus sign
      {"\xE2\x80\x93", "-"},  // U+2013 en dash
      {"\xE2\x80\x94", "-"},  // U+2014 em dash
      {"\xE2\x80\x90", "-"},  // U+2010 hyphen
      {"\xE2\x80\x91", "-"},  // U+2011 non-breaking hyphen
      {"\xCF\x87", "chi"},    // U+03C7 χ
      {"\xCE\xA7", "chi"},    // U+03A7 Χ
      {"\xC2\xB2", "2"},      // U+00B2 ²
      {"\xC2\xA0", " "},      // no-break space
      {"\xE2\x80\x89", " "},  // thin space
      {"\xE2\x80\x8A", " "},  // hair space
      {"\xE2\x80\xAF", " "},  // narrow no-break space (statcheck's getHTML)
      {"\xE2\x89\xA4", "<"},  // ≤ (read as <)
      {"\xE2\x89\xA5", ">"},  // ≥
      {"&lt;", "<"},
      {"&gt;", ">"},
      {"\\chi", "chi"},
      {"\n", " "},
      {"\r", " "},
      {"\t", " "},
      {"\f", " "},
  };
  NormalizedText out;
  out.text.reserve(in.size());
  out.lineStarts.push_back(0);
  for (std::size_t i = 0; i < in.size();) {
    const auto c = static_cast<unsigned char>(in[i]);
    if (c < 0x80 && c != '&' && c != '\\' && c >= ' ') {  // no replacement starts with it
      out.text.push_back(in[i++]);
      continue;
    }
    bool replaced = false;
    for (const auto& r : replacements) {
      if (in.substr(i, r.from.size()) == r.from) {
        out.text += r.to;
        if (r.from == "\n") out.lineStarts.push_back(out.text.size());
        i += r.from.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out.text.push_back(in[i++]);
  }
  return out;
}

std::size_t NormalizedText::lineAt(std::size_t offset) const {
  return static_cast<std::size_t>(std::upper_bound(lineStarts.begin(), lineStarts.end(), offset) - lineStarts.begin());
}

namespace {

RE2::Options latin1() {
  RE2::Options o;
  o.set_encoding(RE2::Options::EncodingLatin1);  // any byte sequence is valid input
  o.set_log_errors(false);
  return o;
}

// Group numbers of apa().
enum Group { Head = 1, Df, FDf1, FDf2, ChiDf, ZHead, TestComp, Junk, Value, PComp, PValue, Ns, GroupCount = Ns };

// One grouping per test layout; numbers are unambiguous (\d+(\.\d+)?|\.\d+), though RE2 would stay
// linear either way.
const RE2& apa() {
  static const RE2 pattern(
      R"((?:(t|r|Q\s*-?\s*(?:[wW]ithin|[bB]etween|w|W|b|B)?)\s*\(\s*(\d+(?:\.\d+)?|\.\d+)\s*\))"
      R"(|F\s*\(\s*(l|I|\d+(?:\.\d+)?|\.\d+)\s*,\s*(\d+(?:\.\d+)?|\.\d+)\s*\))"
      R"(|(?:chi-squared?|chi\s*[\^_]?\s*\{?\s*2?\s*\}?|[Xx]\s*[\^_]?\s*\{?\s*2\s*\}?)\s*\(\s*(\d+(?:\.\d+)?|\.\d+)\s*(?:,\s*[Nn]\s*=\s*\d[\d,]*\s*)?\))"
      R"(|([zZ])))"
      R"(\s*([<>=])\s*((?:[\x80-\xFF]{1,4}|[^A-Za-z0-9.,<>=\s\x80-\xFF]){0,3})\s*)"
      R"((\d+(?:,\d{3})*(?:\.\d+)?|\.\d+)\s*,\s*)"
      R"((?:[pP]\s*([<>=])\s*((?:\d+(?:\.\d+)?|\.\d+)(?:[eE][-+]?\d+)?)|(n\.?s\b\.?)))",
      latin1());
  return pattern;
}

const RE2& pValuePattern() {
  static const RE2 pattern(R"([pP]\s*([<>=])\s*((?:\d+(?:\.\d+)?|\.\d+)(?:[eE][-+]?\d+)?)|(n\.?s\b\.?))", latin1());
  return pattern;
}

bool isLetter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

// Calls f(groups, start) for every match not glued to a preceding letter ("at(28)" is no t-test).
template <int N, class F>
void forEachMatch(const RE2& re, const std::string& text, F f) {
  std::array<re2::StringPiece, N + 1> groups;
  std::size_t pos = 0;
  while (pos <= text.size() &&
         re.Match(text, pos, text.size(), RE2::UNANCHORED, groups.data(), static_cast<int>(groups.size()))) {
    const auto start = static_cast<std::size_t>(groups[0].data() - text.data());
    if (start > 0 && isLetter(text[start - 1])) {
      pos = start + 1;
      continue;
    }
    f(groups, start);
    pos = start + std::max<std::size_t>(groups[0].size(), 1);
  }
}

std::string str(re2::StringPiece s) { return std::string(s.data(), s.size()); }

// A printed number; ".5e-3" and "5e-4" print their last digit at 10^-4, so the exponent shifts
// the decimals (ReportedValue::parse counts the digits after the point only).
ReportedValue reported(const std::string& printed) {
  ReportedValue v = ReportedValue::parse(printed);
  const auto e = printed.find_first_of("eE");
  if (e != std::string::npos) v.decimals -= std::stoi(printed.substr(e + 1));
  return v;
}

std::string withoutCommas(re2::StringPiece s) {
  std::string out;
  for (const char c : s)
    if (c != ',') out.push_back(c);
  return out;
}

PRelation relationOf(char op) { return op == '<' ? PRelation::Less : (op == '>' ? PRelation::Greater : PRelation::Equal); }
TestComparison comparisonOf(char op) {
  return op == '<' ? TestComparison::Less : (op == '>' ? TestComparison::Greater : TestComparison::Equal);
}

StatisticKind headKind(const std::string& head) {
  if (head == "t") return StatisticKind::T;
  if (head == "r") return StatisticKind::R;
  // Q first checks b (Qbetween also holds a w), as statcheck's extract_stats does.
  if (head.find_first_of("bB") != std::string::npos) return StatisticKind::Qb;
  if (head.find_first_of("wW") != std::string::npos) return StatisticKind::Qw;
  return StatisticKind::Q;
}

template <class Groups>
void setKindAndDf(const Groups& m, ApaResult& r) {
  const double na = std::nan("");
  r.df1 = na;
  r.df2 = na;
  if (!m[Head].empty()) {
    r.kind = headKind(str(m[Head]));
    const double df = std::stod(str(m[Df]));
    if (r.kind == StatisticKind::T || r.kind == StatisticKind::R) r.df2 = df;
    else r.df1 = df;
  } else if (!m[FDf2].empty()) {
    r.kind = StatisticKind::F;
    const std::string df1 = str(m[FDf1]);
    r.df1 = (df1 == "l" || df1 == "I") ? 1.0 : std::stod(df1);  // typeset "1" (R/regex.R RGX_DF1_I_L)
    r.df2 = std::stod(str(m[FDf2]));
  } else if (!m[ChiDf].empty()) {
    r.kind = StatisticKind::ChiSquared;
    r.df1 = std::stod(str(m[ChiDf]));
  } else {
    r.kind = StatisticKind::Z;
  }
}

bool dfValid(double df) { return std::isnan(df) || (df > 0.0 && std::isfinite(df)); }

bool plausible(const ApaResult& r) {
  if (!dfValid(r.df1) || !dfValid(r.df2) || !std::isfinite(r.statistic.value)) return false;
  if (r.kind == StatisticKind::R && std::fabs(r.statistic.value) > 1.0) return false;  // misread, not an r
  if (r.pRelation != PRelation::NotSignificant && !(r.p.value <= 1.0)) return false;  // not a p-value
  return true;
}

}  // namespace

std::vector<ApaResult> extractApaResults(std::string_view text) { return extractApaResults(normalizeForStatcheck(text)); }

std::vector<ApaResult> extractApaResults(const NormalizedText& norm) {
  std::vector<ApaResult> results;
  forEachMatch<GroupCount>(apa(), norm.text, [&](const auto& m, std::size_t start) {
    ApaResult r;
    try {
      setKindAndDf(m, r);
      r.testComparison = comparisonOf(m[TestComp][0]);
      // Any stray symbol before the value stands for a minus sign (statcheck's recover_minus_sign).
      std::string value = withoutCommas(m[Value]);
      if (!m[Junk].empty()) value.insert(value.begin(), '-');
      r.statistic = ReportedValue::parse(value);
      if (!m[Ns].empty()) {
        r.pRelation = PRelation::NotSignificant;
      } else {
        r.pRelation = relationOf(m[PComp][0]);
        r.p = reported(str(m[PValue]));
      }
    } catch (const std::logic_error&) {  // std::stod: out of range
      return;
    }
    if (!plausible(r)) return;
    r.text = str(m[0]);
    r.line = norm.lineAt(start);
    results.push_back(r);
  });
  return results;
}

std::vector<ReportedP> extractPValues(std::string_view text) { return extractPValues(normalizeForStatcheck(text)); }

std::vector<ReportedP> extractPValues(const NormalizedText& norm) {
  std::vector<ReportedP> values;
  forEachMatch<3>(pValuePattern(), norm.text, [&](const auto& m, std::size_t start) {
    ReportedP p;
    p.line = norm.lineAt(start);
    if (!m[3].empty()) {
      p.relation = PRelation::NotSignificant;
    } else {
      try {
        p.relation = relationOf(m[1][0]);
        p.p = reported(str(m[2]));
      } catch (const std::logic_error&) {
        return;
      }
    }
    values.push_back(p);
  });
  return values;
}

bool mentionsOneTailed(std::string_view text) {
  static const RE2 pattern(R"((?i)one.?sided|one.?tailed|directional)", latin1());
  return RE2::PartialMatch(re2::StringPiece(text.data(), text.size()), pattern);
}

}  // namespace tlab::analysis
