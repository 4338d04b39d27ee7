#pragma once
// The results of a study's planned analysis as a plain-text table (tlab analyze, tlab demo).
#include <string>

#include "study/analyze/study_analysis.hpp"

namespace tlab::app {

std::string analysisText(const study::StudyAnalysis& analysis);

}  // namespace tlab::app
