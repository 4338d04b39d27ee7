#pragma once
// What the store tests share: a plan of one fake trial and the hostile texts stores must keep.
#include <string>
#include <vector>

#include "study/store/store.hpp"

namespace tlab::testing {

inline study::TrialRecord fakeTrial(int sequence) {
  study::TrialRecord t;
  t.sequence = sequence;
  t.phase = "test";
  t.block = 1;
  t.condition = "method=alpha, scene=cylinders";
  t.levelsJson = R"({"method":"alpha","scene":"cylinders"})";
  t.taskId = "layer";
  t.task = "layer-index";
  t.stimulusKey = "k";
  t.questionJson = "{}";
  t.answerKind = "layer-number";
  t.truthJson = "2";
  t.timeLimitSeconds = 30;
  t.stimulusPath = "s.png";
  t.stimulusSha256 = std::string(64, 'a');
  return t;
}

inline std::string invalidUtf8Text() { return "bad \xC3\x28 \xFF\xFE \xE2\x82 end"; }

// Quotes, SQL, line breaks, 1 MB, blanks, "NULL", and (withInvalidUtf8) bytes that are not UTF-8.
inline std::vector<std::string> hostileTexts(bool withInvalidUtf8 = true) {
  std::string big(1 << 20, 'x');
  for (std::size_t i = 0; i < big.size(); i += 997) big[i] = "\",'\n;\r"[i % 6];
  std::vector<std::string> texts = {"'; DROP TABLE responses; --", "Robert\"); DROP TABLE participants;--", "comma, \"quote\" and\nnewline"};
  if (withInvalidUtf8) texts.push_back(invalidUtf8Text());
  texts.insert(texts.end(), {big, " leading and trailing ", "", "NULL"});
  return texts;
}

}  // namespace tlab::testing
