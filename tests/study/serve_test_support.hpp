#pragma once
// Shared helpers of the `tlab serve` load tests: what `tlab export --csv` stored per trial (the
// server itself runs as a ServedStudy, tests/study/served_study.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <thread>

#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

namespace tlab::testing {

struct StoredTrial {
  std::string status;  // the participant's
  std::string phase;
  int position = 0;    // among the participant's trials of its phase, from 1 (the page's "index")
  std::string rawAnswer;
  int rows = 0;        // one per stored response (a trial without a response: one row, responded 0)
  int responded = 0;
};

// (participant, sequence) → what trials.csv of `tlab export --csv` holds.
inline std::map<std::pair<std::string, int>, StoredTrial> exportedTrials(const std::filesystem::path& dir) {
  const auto rows = exportedTable((dir / "study.db").string(), dir, "trials");
  std::map<std::pair<std::string, int>, StoredTrial> out;
  if (rows.empty()) return out;
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < rows[0].size(); ++c) column[rows[0][c]] = c;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    StoredTrial& t = out[{row.at(column.at("participant")), std::stoi(row.at(column.at("sequence")))}];
    t.status = row.at(column.at("participant_status"));
    t.phase = row.at(column.at("phase"));
    t.rawAnswer = row.at(column.at("raw_answer"));
    t.responded += row.at(column.at("responded")) == "1";
    ++t.rows;
  }
  std::map<std::pair<std::string, std::string>, int> positions;  // trials come in sequence order
  for (auto& [key, t] : out) t.position = ++positions[{key.first, t.phase}];
  return out;
}

// The stored trial the page showed as `phase` trial `index` of `participant` (nullptr if none).
inline const StoredTrial* storedTrialAt(const std::map<std::pair<std::string, int>, StoredTrial>& trials, const std::string& participant,
                                        const std::string& phase, int index) {
  for (const auto& [key, t] : trials)
    if (key.first == participant && t.phase == phase && t.position == index) return &t;
  return nullptr;
}

}  // namespace tlab::testing
