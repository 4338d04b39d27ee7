// Each task's question and each refused answer reach participants through the text table
// (issue #26 §4): the key's English text with the question's values is exactly the task's own
// English text, and every shipped language says it in its own words.
#include <gtest/gtest.h>

#include "../tasks/task_test_scenes.hpp"
#include "renderer/scene/builtin_scenes.hpp"
#include "study/design/participant_texts.hpp"
#include "study/run/session_wording.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/answer_parser.hpp"
#include "tasks/letter_patterns.hpp"
#include "tasks/task_registry.hpp"

namespace tlab::study {
namespace {

using render::Role;

std::vector<tasks::Question> probeBuiltin(const std::string& task, const std::string& scene, std::vector<std::string> settings = {}) {
  const render::Scene s = render::buildBuiltinScene(scene, render::builtinScenes());
  const auto t = tasks::makeTask(task);
  const render::Camera camera = render::fitCamera(s.boundingSphere(), 1.0f);
  return t->probe({s, camera, 400, 400, 2, 3, t->settings(settings)});
}

std::vector<tasks::Question> probeFloorScene(const std::string& task, std::vector<std::string> settings = {}) {
  render::Scene scene;
  int i = 0;
  for (const auto& p : tasks::letterFloorPositions('K', {-3.0, -4.0}, 1.2, 0.9))
    scene.objects.push_back(tasks::testing::boxAt("cone-" + std::to_string(++i), p, Role::Target));
  scene.objects.push_back(tasks::testing::boxAt("box-1", {-6.0, 5.0}, Role::Distractor));
  if (task == "target-discovery") {  // one target only
    scene.objects.clear();
    scene.objects.push_back(tasks::testing::boxAt("dog", {2.0, -1.0}, Role::Target));
  }
  const auto t = tasks::makeTask(task);
  render::Camera camera;
  camera.eye = {0.0f, 12.0f, 12.0f};
  return t->probe({scene, camera, 320, 240, 1, 1, t->settings(settings)});
}

// Every task's questions: {task, settings} probed on a scene it works on.
std::vector<tasks::Question> everyTasksQuestions() {
  std::vector<tasks::Question> all;
  const auto add = [&](std::vector<tasks::Question> qs) { all.insert(all.end(), qs.begin(), qs.end()); };
  add(probeBuiltin("layer-index", "open-cylinders"));
  add(probeBuiltin("follow-boundary", "open-cylinders"));
  add(probeBuiltin("nearest-point", "open-cylinders"));
  add(probeBuiltin("gauge-figure", "nested-spheres?n=3"));
  add(probeBuiltin("gauge-figure", "nested-spheres?n=3", {"layer=2"}));
  add(probeBuiltin("relative-depth", "nested-spheres?n=3", {"layer-b=2"}));
  add(probeFloorScene("counting"));
  add(probeFloorScene("counting", {"kind=cone"}));
  add(probeFloorScene("pattern"));
  add(probeFloorScene("target-discovery"));
  return all;
}

TEST(QuestionWording, EveryTasksKeyGivesItsEnglishTextAndEveryLanguageItsOwnWords) {
  const auto questions = everyTasksQuestions();
  std::set<std::string> tasksSeen, keysSeen;
  const ParticipantTexts en, de("de"), fr("fr");
  for (const auto& q : questions) {
    tasksSeen.insert(q.task);
    keysSeen.insert(q.textKey);
    ASSERT_FALSE(q.textKey.empty()) << q.task << ": " << q.text;
    ASSERT_TRUE(en.has(q.textKey)) << q.textKey;
    EXPECT_EQ(questionWording(q, en), q.text) << q.textKey;
    for (const ParticipantTexts* other : {&de, &fr}) {
      const std::string words = questionWording(q, *other);
      EXPECT_NE(words, q.text) << other->language() << ": " << q.textKey;
      EXPECT_EQ(words.find('{'), std::string::npos) << other->language() << ": a value left out: " << words;
    }
  }
  for (const auto& name : tasks::taskNames()) EXPECT_TRUE(tasksSeen.count(name)) << name << " has no question in this test";
  // The values reach the words: the kind counted, the gauge's layer.
  for (const auto& q : questions) {
    if (q.textKey == "question.counting_kind") {
      EXPECT_NE(questionWording(q, de).find("cone"), std::string::npos);
    }
    if (q.textKey == "question.gauge_figure_layer") {
      EXPECT_NE(questionWording(q, de).find("2. Fläche"), std::string::npos) << questionWording(q, de);
      EXPECT_EQ(q.text, "Turn the gauge until its disk lies flat on surface 2 from the front.");
    }
  }
  EXPECT_EQ(keysSeen.size(), 10u);
  // An experiment's [text] overrides a question like any other key.
  ParticipantTexts mine;
  mine.set("question.layer_index", "Which layer is at A?");
  for (const auto& q : questions)
    if (q.task == "layer-index") {
      EXPECT_EQ(questionWording(q, mine), "Which layer is at A?");
    }
}

TEST(QuestionWording, QuestionsWithoutAKeyKeepTheirText) {
  tasks::Question q;
  q.text = "Look at the marked points.";
  EXPECT_EQ(questionWording(q, ParticipantTexts("de")), "Look at the marked points.");
}

// Every refusal a participant's typing can cause names a key; its words in German carry the values.
TEST(RefusalWording, TypedAnswersRefusedInTheParticipantsLanguage) {
  const ParticipantTexts en, de("de");
  tasks::Question labels;
  labels.answerKind = tasks::AnswerKind::Label;
  labels.points = {{"A", "candidate"}, {"B", "candidate"}};
  tasks::Question set = labels;
  set.answerKind = tasks::AnswerKind::LabelSet;
  struct Case {
    tasks::AnswerKind kind;
    const tasks::Question* question;
    std::string typed, key, german;
  };
  tasks::Question layer, count, floor, letter, direction;
  layer.answerKind = tasks::AnswerKind::LayerNumber;
  count.answerKind = tasks::AnswerKind::Count;
  floor.answerKind = tasks::AnswerKind::FloorPoint;
  letter.answerKind = tasks::AnswerKind::Letter;
  direction.answerKind = tasks::AnswerKind::Direction;
  const std::vector<Case> cases = {
      {tasks::AnswerKind::LayerNumber, &layer, "0", "refusal.layer_number", "Bitte geben Sie die Nummer der Schicht ein: eine ganze Zahl ab 1 (1 ist vorn)."},
      {tasks::AnswerKind::Count, &count, "-1", "refusal.count", "Bitte geben Sie eine ganze Zahl ab 0 ein."},
      {tasks::AnswerKind::Label, &labels, "A B", "refusal.one_label", "Bitte nennen Sie einen der markierten Punkte: A, B."},
      {tasks::AnswerKind::Label, &labels, "Q", "refusal.not_a_label", "„Q“ ist keiner der markierten Punkte (A, B)."},
      {tasks::AnswerKind::LabelSet, &set, "A a", "refusal.label_twice", "„a“ ist zweimal angegeben."},
      {tasks::AnswerKind::FloorPoint, &floor, "1;2", "refusal.floor_point", "Bitte geben Sie einen Ort auf dem Grundriss als zwei Zahlen x,z an."},
      {tasks::AnswerKind::FloorPoint, &floor, "1,x", "refusal.floor_point", "Bitte geben Sie einen Ort auf dem Grundriss als zwei Zahlen x,z an."},
      {tasks::AnswerKind::Letter, &letter, "Q", "refusal.letter", "Bitte nennen Sie einen der Buchstaben C, K, R, X oder Y."},
      {tasks::AnswerKind::Direction, &direction, "0,0,0", "refusal.direction", "Bitte geben Sie eine Richtung als drei Zahlen x,y,z an (nicht alle 0)."},
  };
  for (const auto& c : cases) {
    try {
      tasks::parseAnswer(*c.question, c.typed);
      ADD_FAILURE() << c.typed << " was accepted";
    } catch (const tasks::AnswerFormatError& e) {
      EXPECT_EQ(e.key(), c.key) << c.typed;
      EXPECT_EQ(refusalWording(e, de), c.german) << c.typed;
      EXPECT_TRUE(en.has(c.key));
      EXPECT_EQ(std::string(e.what()).rfind("answer: ", 0), 0u) << "the English message stays for logs: " << e.what();
    }
  }
  // A refusal without a key (no participant's input causes it) is said in English, without the prefix.
  EXPECT_EQ(refusalWording(tasks::AnswerFormatError("answer: broken"), de), "broken");
}

}  // namespace
}  // namespace tlab::study
