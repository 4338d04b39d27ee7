// The load client's pure parts: answers chosen from what a page offers, the form values, the
// images a page shows, the link it is given and the percentiles it prints.
#include <gtest/gtest.h>

#include "study/design/form_field.hpp"
#include "study/serve/load_answers.hpp"
#include "study/serve/load_client.hpp"

using nlohmann::json;
using namespace tlab::study;

// A trial page as the server sends it: its widget (tasks/answer_form.hpp) and the marks to click.
json page(const json& widget, const json& extra = json::object()) {
  json p{{"widget", widget}};
  p.update(extra);
  return p;
}

TEST(LoadAnswers, EveryWidgetIsAnsweredFromWhatThePageOffers) {
  std::mt19937_64 rng(1);
  const json labels = json::array({{{"label", "A"}, {"x", 1}, {"y", 2}}, {{"label", "B"}, {"x", 3}, {"y", 4}}});
  for (int i = 0; i < 50; ++i) {
    const int n = loadAnswer(page({{"kind", "number"}, {"min", 1}}), 5.0, rng)["answer"].get<int>();
    EXPECT_TRUE(n >= 1 && n <= 5);
    const std::string l = loadAnswer(page({{"kind", "pick-label"}}, {{"labels", labels}}), 5.0, rng)["answer"].get<std::string>();
    EXPECT_TRUE(l == "A" || l == "B");
    const json set = loadAnswer(page({{"kind", "pick-labels"}}, {{"labels", labels}}), 5.0, rng)["answer"];
    EXPECT_TRUE(set.is_array() && !set.empty() && set.size() <= 2);
    EXPECT_EQ(loadAnswer(page({{"kind", "buttons"}, {"buttons", {"K"}}}), 5.0, rng)["answer"], "K");
    const json p = loadAnswer(page({{"kind", "floor-plan"}}, {{"floor_plan", {{"width", 3}, {"height", 2}}}}), 5.0, rng)["answer"];
    EXPECT_TRUE(p["x"].get<double>() > 0 && p["x"].get<double>() < 3 && p["y"].get<double>() > 0 && p["y"].get<double>() < 2);
    const json g = loadAnswer(page({{"kind", "gauge"}}), 5.0, rng)["answer"];
    EXPECT_TRUE(g["slant"].get<double>() >= 0 && g["slant"].get<double>() <= 80 && g["tilt"].get<double>() >= 0 && g["tilt"].get<double>() < 360);
  }
  EXPECT_EQ(loadAnswer(page({{"kind", "pick-label"}}, {{"labels", json::array()}}), 5.0, rng), json({{"type", "timeout"}}));
  EXPECT_EQ(loadAnswer(page({{"kind", "number"}, {"min", 0}}), 7.5, rng)["rt_ms"], 7.5);
}

TEST(LoadAnswers, FormValuesPassTheServersFieldCheck) {
  std::vector<FormField> fields(4);
  fields[0].kind = FieldKind::Likert;
  fields[0].points = 7;
  fields[1].kind = FieldKind::Choice;
  fields[1].options = {"yes", "no"};
  fields[2].kind = FieldKind::Number;
  fields[2].minimum = 18;
  fields[2].maximum = 99;
  fields[2].integer = true;
  fields[3].kind = FieldKind::Text;
  fields[3].required = true;
  const json page{{"kind", "form"},
                  {"fields", {{{"kind", "likert"}, {"points", 7}}, {{"kind", "choice"}, {"options", {"yes", "no"}}},
                              {{"kind", "number"}, {"min", 18}, {"max", 99}, {"integer", true}}, {{"kind", "text"}, {"required", true}}}}};
  std::mt19937_64 rng(2);
  const json body = loadFormValues(page, rng);
  ASSERT_EQ(body["values"].size(), 4u);
  for (std::size_t i = 0; i < fields.size(); ++i) EXPECT_EQ(fieldError(fields[i], body["values"][i].get<std::string>()), "") << i;
}

TEST(LoadAnswers, APageShowsItsStimulusFloorPlanAndTurntableViews) {
  const json page{{"image", {{"sha256", "a"}}}, {"floor_plan", {{"sha256", "b"}}}, {"turntable", {{"views", {{{"sha256", "c"}}, {{"sha256", "d"}}}}}}};
  EXPECT_EQ(pageImages(page), (std::vector<std::string>{"a", "b", "c", "d"}));
  EXPECT_TRUE(pageImages({{"kind", "message"}}).empty());
}

TEST(LoadClient, TheLinkIsSplitAndMalformedOnesAreRefused) {
  const LoadTarget t = parseLoadTarget("http://127.0.0.1:8080/s/tiny", "pid");
  EXPECT_EQ(t.origin, "http://127.0.0.1:8080");
  EXPECT_EQ(t.arrivalPath, "/s/tiny");
  EXPECT_THROW(parseLoadTarget("https://x/s/tiny", "pid"), std::invalid_argument);
  EXPECT_THROW(parseLoadTarget("http://x:1/s/tiny?pid=1", "pid"), std::invalid_argument);
  EXPECT_THROW(parseLoadTarget("http://x:1", "pid"), std::invalid_argument);
  EXPECT_EQ(loadParticipantId("load-", 0), "load-001");
}

TEST(LoadClient, PercentilesAreNearestRank) {
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);
  const Percentiles p = percentiles(v);
  EXPECT_EQ(p.count, 100u);
  EXPECT_EQ(p.p50, 50);
  EXPECT_EQ(p.p95, 95);
  EXPECT_EQ(p.p99, 99);
  EXPECT_EQ(p.max, 100);
  EXPECT_EQ(percentiles({}).count, 0u);
}
