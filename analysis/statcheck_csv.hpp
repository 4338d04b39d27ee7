#pragma once
// statcheck reports as CSV that R reads (read.csv) next to statcheck's own data frame: statcheck's
// column names and order (source, test_type, df1, df2, test_comp, test_value, p_comp, reported_p,
// computed_p, raw, error, decision_error, one_tailed_in_txt, apa_factor), then tlab's extra
// columns. Missing values are NA, logicals TRUE/FALSE, numbers in their shortest round-trip
// form (they read back to the same double), text quoted with "" for a quote (RFC 4180).
#include <ostream>
#include <vector>

#include "analysis/statcheck.hpp"

namespace tlab::analysis {

void writeStatcheckCsv(std::ostream& out, const std::vector<StatcheckReport>& reports);
// statcheck's AllPValues = TRUE list: source, p_comp, reported_p, p_decimals, then line.
void writePValuesCsv(std::ostream& out, const std::vector<StatcheckReport>& reports);
// statcheck rounds the APA factor to two decimals.
double roundedApaFactor(const StatcheckReport& report);

}  // namespace tlab::analysis
