#pragma once
// Outlier screening of one cell (Carnecky Sec. 8.2 "we check the data for outliers"). Two rules,
// each reported separately so a report can say which flagged what:
//  - Tukey fences (Tukey 1977, Exploratory Data Analysis): x < Q1 - 1.5·IQR or x > Q3 + 1.5·IQR,
//    quartiles by R's type 7 (the rule behind box-plot whiskers);
//  - |z| > 3 with z = (x - mean)/sd, the sample sd with divisor n - 1.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace tlab::analysis {

enum class OutlierRule { TukeyFences, AbsoluteZAbove3 };
std::string_view outlierRuleName(OutlierRule rule);  // "Tukey fences (1.5 IQR)", "|z| > 3"

struct Outlier {
  std::size_t index = 0;  // position in the screened sample
  double value = 0.0;
  double z = 0.0;
  OutlierRule rule = OutlierRule::TukeyFences;
};

struct OutlierScreen {
  double lowerFence = 0.0;  // Q1 - 1.5 IQR
  double upperFence = 0.0;  // Q3 + 1.5 IQR
  std::vector<Outlier> outliers;  // one entry per (value, rule) that flagged it
};

OutlierScreen screenOutliers(std::span<const double> xs);

}  // namespace tlab::analysis
