// Replies whose fields have JSON types a screen's check does not expect are refused with a
// message on every kind of screen (found by fuzz/serve_reply_fuzzer: {"seq": 1, "type": true}
// made the checks throw, so POST /reply answered 500 and kept no refused-reply event).
#include <gtest/gtest.h>

#include "study/serve/flow_pages.hpp"
#include "study/serve/trial_page.hpp"

using nlohmann::json;
using namespace tlab::study;

namespace {

std::vector<Screen> everyKindOfScreen(const PlannedTrial& plan, const PreparedTrial& prepared) {
  std::vector<FormField> fields(1);
  const TrialView view{plan, prepared, 30.0, 1, 1, {}};
  return {messageScreen("T", "x"), consentScreen("T", {"Agree?"}), formScreen("T", fields, ParticipantTexts()), feedbackScreen(view, {true, "2", "2"}),
          breakScreen({}), trialScreen(view, {})};
}

}  // namespace

TEST(ServeReplyCheck, AReplyTypeThatIsNotATextIsRefusedWithAMessageOnEveryScreen) {
  PlannedTrial plan;
  PreparedTrial prepared;
  prepared.question.answerKind = tlab::tasks::AnswerKind::LayerNumber;
  for (const Screen& screen : everyKindOfScreen(plan, prepared)) {
    for (const json& type : {json(true), json(3), json::array(), json(nullptr)}) {
      SessionChannel channel(std::chrono::minutes(1));
      const int seq = channel.publish(screen);
      std::string error;
      const json body{{"seq", seq}, {"type", type}, {"answer", 2}, {"rt_ms", 5}};
      EXPECT_EQ(channel.deliver(seq, body, 1, error), SessionChannel::Delivery::Refused) << screen.page.dump() << " " << body.dump();
      EXPECT_FALSE(error.empty());
      EXPECT_EQ(channel.takeRefusals().size(), 1u);
    }
  }
}

// A reply to a screen no longer shown is stale whatever its fields hold: {"type": ["D"]} made the
// stale path's check for a late answer throw (found by fuzz/serve_request_fuzzer), so POST /reply
// answered 500 instead of saying the screen has gone. A late answer is still kept as an event.
TEST(ServeReplyCheck, AStaleReplyOfAnyTypeIsStaleAndALateAnswerIsKept) {
  PlannedTrial plan;
  PreparedTrial prepared;
  SessionChannel channel(std::chrono::minutes(1));
  const int seq = channel.publish(messageScreen("T", "x"));
  for (const json& type : {json::array({"D"}), json(true), json(3), json(nullptr), json::object()}) {
    std::string error;
    EXPECT_EQ(channel.deliver(seq + 1, json{{"seq", seq + 1}, {"type", type}, {"rt_ms", 0}}, 1, error), SessionChannel::Delivery::Stale)
        << type.dump();
    EXPECT_NE(error.find("is no longer shown"), std::string::npos) << error;
  }
  EXPECT_TRUE(channel.takeEvents().empty());
  std::string error;
  EXPECT_EQ(channel.deliver(seq + 1, json{{"seq", seq + 1}, {"type", "answer"}, {"answer", 2}}, 1, error), SessionChannel::Delivery::Stale);
  const auto events = channel.takeEvents();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, "late-answer");
}
