// Texts from requests that are not UTF-8, or are cut inside a character, reach JSON that the
// server sends or stores (nlohmann's dump() throws on invalid UTF-8). Found while writing the
// serve fuzz targets: a reply with a long non-ASCII body made POST /reply answer 500 instead of
// 400 and lost its refused-reply event, an unknown reply type cut at 40 bytes did the same, and a
// User-Agent with a byte like 0xff made every POST /display of that participant fail with 500.
#include <gtest/gtest.h>

#include <httplib.h>

#include "study/serve/flow_pages.hpp"
#include "study/serve/request_checks.hpp"
#include "tests/study/serve_test_support.hpp"

using nlohmann::json;
using namespace tlab::study;
using namespace tlab::testing;

namespace {

std::string repeated(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

}  // namespace

TEST(ServeRequestText, ARefusedReplyCutInsideACharacterIsRefusedWithAMessageAndKept) {
  SessionChannel channel(std::chrono::minutes(1));
  const int seq = channel.publish(messageScreen("Title", "Text"));
  std::string error;
  const json body{{"type", repeated("\xc3\xa9", 300)}};  // é × 300: the stored body is cut at 500 bytes
  EXPECT_EQ(channel.deliver(seq, body, 1, error), SessionChannel::Delivery::Refused);
  EXPECT_FALSE(error.empty());
  const auto refusals = channel.takeRefusals();
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_NO_THROW(json::parse(refusals[0].second));
}

TEST(ServeRequestText, ErrorMessagesQuotingACutTextAreSentAsJson) {
  const std::string cut = std::string("unknown reply type '") + repeated("\xc3\xa9", 30).substr(0, 39) + "'";
  EXPECT_THROW(json({{"error", cut}}).dump(), json::type_error);
  const json sent = json::parse(jsonText({{"error", cut}}));
  EXPECT_EQ(sent["error"].get<std::string>().substr(0, 20), "unknown reply type '");
}

TEST(ServeRequestText, AnArrivalRecordIsValidUtf8WhateverTheBrowserSends) {
  const json a = arrivalRecord("p1", "Mozilla \xff\xfe" + repeated("\xe2\x82\xac", 200), {{"STUDY_ID", "\xc3"}});
  EXPECT_NO_THROW(a.dump());
  EXPECT_EQ(a["participant"], "p1");
  EXPECT_LE(a["user_agent"].get<std::string>().size(), 400u + 3 * 3);  // cut at 400 bytes; each bad byte became 3
  EXPECT_EQ(a["STUDY_ID"], "\xef\xbf\xbd");  // U+FFFD
  EXPECT_TRUE(validParticipantId("PROLIFIC_5f2a.b@c-d"));
  EXPECT_FALSE(validParticipantId("a b"));
  EXPECT_FALSE(validParticipantId(std::string(129, 'a')));
  EXPECT_EQ(checkDisplay({{"w", 1}, {"ua", "x"}}), std::nullopt);
  EXPECT_NE(checkDisplay({{"nested", json::object()}}), std::nullopt);
}

TEST(ServeRequestText, ABrowserWithANonUtf8UserAgentStartsItsSession) {
  const auto dir = freshDir("serve_user_agent");
  ServedStudy server(studyData("tiny.toml"), (dir / "study.db").string(), dir);
  httplib::Client client("127.0.0.1", server.port());
  const auto arrived = client.Get("/s/tiny?pid=ua-1", {{"User-Agent", "Mozilla/5.0 \xff\xfe"}});
  ASSERT_TRUE(arrived);
  ASSERT_EQ(arrived->status, 303);
  const std::string token = arrived->get_header_value("Location").substr(3);
  const auto shown = client.Post(("/api/" + token + "/display").c_str(), R"({"window_width": 800})", "application/json");
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->status, 200) << shown->body;
  EXPECT_EQ(json::parse(shown->body).value("kind", ""), "message");
  EXPECT_EQ(server.stop(SIGTERM), 0);
}
