#include "analysis/statcheck_csv.hpp"

#include <cmath>
#include <charconv>
#include <string>

namespace tlab::analysis {

namespace {

std::string num(double x) {
  if (!std::isfinite(x)) return "NA";
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;  // shortest round-trip form
  return std::string(buffer, end);
}

std::string logical(bool b) { return b ? "TRUE" : "FALSE"; }

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

double reportedP(PRelation relation, const ReportedValue& p) {
  return relation == PRelation::NotSignificant ? std::nan("") : p.value;
}

}  // namespace

double roundedApaFactor(const StatcheckReport& report) {
  const double f = report.apaFactor();
  return std::isfinite(f) ? std::round(f * 100.0) / 100.0 : f;
}

void writeStatcheckCsv(std::ostream& out, const std::vector<StatcheckReport>& reports) {
  out << "source,test_type,df1,df2,test_comp,test_value,p_comp,reported_p,computed_p,raw,error,decision_error,"
         "one_tailed_in_txt,apa_factor,line,test_decimals,p_decimals,one_tailed,consistent_if_one_tailed,"
         "computed_p_low,computed_p_high,note\n";
  for (const auto& report : reports) {
    for (const auto& v : report.verdicts) {
      const ApaResult& r = v.result;
      const bool ns = r.pRelation == PRelation::NotSignificant;
      out << quoted(report.source) << ',' << quoted(statisticName(r.kind)) << ',' << num(r.df1) << ','
          << num(r.df2) << ',' << quoted(comparisonSymbol(r.testComparison)) << ',' << num(r.statistic.value) << ','
          << quoted(pRelationSymbol(r.pRelation)) << ',' << num(reportedP(r.pRelation, r.p)) << ','
          << num(v.pComputed) << ',' << quoted(r.text) << ',' << logical(!v.consistent) << ','
          << logical(v.decisionError) << ',' << logical(report.oneTailedInText) << ','
          << num(roundedApaFactor(report)) << ',' << r.line << ',' << r.statistic.decimals << ','
          << (ns ? "NA" : std::to_string(r.p.decimals)) << ',' << logical(v.oneTailed) << ','
          << logical(v.consistentIfOneTailed) << ',' << num(v.pRange.lo) << ',' << num(v.pRange.hi) << ','
          << quoted(v.note) << '\n';
    }
  }
}

void writePValuesCsv(std::ostream& out, const std::vector<StatcheckReport>& reports) {
  out << "source,p_comp,reported_p,p_decimals,line\n";
  for (const auto& report : reports)
    for (const auto& p : report.pValues) {
      const bool ns = p.relation == PRelation::NotSignificant;
      out << quoted(report.source) << ',' << quoted(pRelationSymbol(p.relation)) << ','
          << num(reportedP(p.relation, p.p)) << ',' << (ns ? "NA" : std::to_string(p.p.decimals)) << ',' << p.line
          << '\n';
    }
}

}  // namespace tlab::analysis
