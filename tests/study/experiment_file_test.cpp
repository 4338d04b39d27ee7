// The experiment file: what it holds after parsing, and one-line errors naming file:line and the
// field for every kind of bad input.
#include <gtest/gtest.h>

#include "study/design/experiment_file.hpp"
#include "study/design/form_field.hpp"
#include "tests/study/study_test_support.hpp"

using namespace tlab::study;

namespace {

const std::string kBase = R"(id = "x"
participants = 4
counterbalancing = "latin-square"
[[factors]]
name = "method"
levels = ["a", "b"]
[[tasks]]
task = "layer-index"
)";

std::string errorOf(const std::string& text) {
  try {
    parseExperiment(text, "bad.toml");
  } catch (const ExperimentFileError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ExperimentFile, ReadsTheExamples) {
  const Experiment c = readExperimentFile(tlab::testing::example("carnecky2013.toml"));
  EXPECT_EQ(c.id, "carnecky2013");
  EXPECT_EQ(c.counterbalancing, Counterbalancing::GraecoLatin);
  EXPECT_EQ(c.blockTasks, BlockTasks::ByPosition);
  ASSERT_EQ(c.factors.size(), 2u);
  EXPECT_EQ(c.factors[0].levels[1].name, "normal-variation");
  EXPECT_EQ(c.factors[0].levels[1].style.value_or(""), "normal-variation");
  EXPECT_EQ(c.factors[1].levels[0].scene.value_or(""), "builtin:pretzel");
  ASSERT_EQ(c.tasks.size(), 3u);
  EXPECT_EQ(c.tasks[0].trialTimeLimitSeconds.value_or(0), 120.0);
  ASSERT_EQ(c.analyses.size(), 1u);
  EXPECT_EQ(c.analyses[0].within, std::vector<std::string>{"method"});
  EXPECT_EQ(c.questionnaires.at(0).items.size(), 2u);

  const Experiment e = readExperimentFile(tlab::testing::example("elmqvist.toml"));
  EXPECT_EQ(e.tasks.size(), 4u);
  EXPECT_EQ(e.tasks[1].scene.value_or(""), "builtin:abstract-pattern?letter={trial}&seed={trial}");
  EXPECT_EQ(e.tasks[3].when.at("scenario"), "walkthrough");
  EXPECT_EQ(e.factors[0].levels[1].style.value_or(""), "dynamic");  // parses before the style exists
}

TEST(ExperimentFile, TheOnlineTableIsReadAndChecked) {
  const Experiment o = readExperimentFile(tlab::testing::example("online.toml"));
  EXPECT_EQ(o.online.participantParameter, "PROLIFIC_PID");
  EXPECT_EQ(o.online.studyParameter, "STUDY_ID");
  EXPECT_EQ(o.online.timeoutMinutes, 30.0);
  EXPECT_TRUE(o.online.sizeCalibration);
  EXPECT_EQ(o.online.completionUrl, "https://app.prolific.com/submissions/complete?cc=TLABDEMO");
  const Experiment d = readExperimentFile(tlab::testing::studyData("tiny.toml"));
  EXPECT_EQ(d.online.participantParameter, "pid");  // the defaults
  EXPECT_EQ(d.online.turntableAzimuths * d.online.turntableElevations, 180);
  EXPECT_EQ(errorOf(kBase + "[online]\ncompletion_url = \"ftp://x\"\n"), "bad.toml:10: online.completion_url: must start with https:// or http://");
  EXPECT_EQ(errorOf(kBase + "[online]\nturntable_azimuths = 100\nturntable_elevations = 9\n"),
            "bad.toml:10: online.turntable_azimuths: at most 720 views in all (azimuths x elevations)");
  EXPECT_EQ(errorOf(kBase + "[online]\nparticipant_parameter = \"\"\n"), "bad.toml:10: online.participant_parameter: must not be empty");
  EXPECT_NE(errorOf(kBase + "[online]\nport = 80\n").find("bad.toml:10: online.port: unknown key"), std::string::npos);
}

TEST(ExperimentFile, StimulusSizeDevicesAndCalibrationOnline) {
  const Experiment d = parseExperiment(kBase, "d.toml", StimulusChecks::Skip);
  EXPECT_EQ(d.online.stimulusSize, "native");  // the defaults
  EXPECT_EQ(d.online.devices, std::vector<std::string>{"desktop"});
  EXPECT_FALSE(d.online.calibrationNoCard);
  const Experiment cm = parseExperiment(kBase + "[online]\nsize_calibration = true\ncalibration_no_card = true\nstimulus_size = \"10cm\"\n"
                                                "devices = [\"desktop\", \"tablet\"]\n",
                                        "cm.toml", StimulusChecks::Skip);
  EXPECT_EQ(cm.online.stimulusSize, "cm");
  EXPECT_EQ(cm.online.stimulusCm, 10.0);
  EXPECT_TRUE(cm.online.calibrationNoCard);
  EXPECT_EQ(cm.online.devices, (std::vector<std::string>{"desktop", "tablet"}));
  EXPECT_EQ(parseExperiment(kBase + "[online]\nstimulus_size = \"css\"\n", "c.toml", StimulusChecks::Skip).online.stimulusSize, "css");
  EXPECT_EQ(errorOf(kBase + "[online]\nstimulus_size = \"10cm\"\n"),
            "bad.toml:10: online.stimulus_size: a size in cm needs size_calibration = true (the page must know its pixels per cm)");
  EXPECT_EQ(errorOf(kBase + "[online]\nstimulus_size = \"big\"\n"),
            "bad.toml:10: online.stimulus_size: expected \"native\", \"css\" or a width such as \"10cm\" (up to 100 cm), got 'big'");
  EXPECT_EQ(errorOf(kBase + "[online]\ndevices = [\"watch\"]\n"), "bad.toml:10: online.devices: expected desktop, tablet or phone, got 'watch'");
  EXPECT_EQ(errorOf(kBase + "[online]\ndevices = []\n"), "bad.toml:10: online.devices: at least one kind of device must be allowed");
}

// How live frames are sent (issue #30): lossless PNG unless the experiment chooses JPEG at a quality.
TEST(ExperimentFile, LiveFramesArePngUnlessJpegIsChosen) {
  const Experiment d = parseExperiment(kBase, "d.toml", StimulusChecks::Skip);
  EXPECT_EQ(d.online.frames, "png");
  const Experiment j = parseExperiment(kBase + "[online]\nframes = \"jpeg\"\njpeg_quality = 75\n", "j.toml", StimulusChecks::Skip);
  EXPECT_EQ(j.online.frames, "jpeg");
  EXPECT_EQ(j.online.jpegQuality, 75);
  EXPECT_EQ(parseExperiment(kBase + "[online]\nframes = \"jpeg\"\n", "q.toml", StimulusChecks::Skip).online.jpegQuality, 90);
  EXPECT_EQ(errorOf(kBase + "[online]\nframes = \"gif\"\n"), "bad.toml:10: online.frames: expected \"png\" (lossless) or \"jpeg\" (lossy), got 'gif'");
  EXPECT_EQ(errorOf(kBase + "[online]\nframes = \"jpeg\"\njpeg_quality = 101\n"), "bad.toml:11: online.jpeg_quality: must be between 1 and 100");
  EXPECT_EQ(errorOf(kBase + "[online]\nframes = \"jpeg\"\njpeg_quality = 0\n"), "bad.toml:11: online.jpeg_quality: must be >= 1");
  EXPECT_EQ(errorOf(kBase + "[online]\njpeg_quality = 80\n"), "bad.toml:10: online.jpeg_quality: only with frames = \"jpeg\"");
}

TEST(ExperimentFile, ErrorsNameFileLineAndField) {
  EXPECT_EQ(errorOf("extra = 1\n" + kBase), "bad.toml:1: extra: unknown key (known: analysis, block_tasks, breaks, consent, counterbalancing, "
                                            "debrief, factors, goodbye, id, info, language, observer, online, participant_title, participants, "
                                            "questionnaires, seed, standard_info, stimulus, tasks, text, title, training, welcome)");
  EXPECT_EQ(errorOf(kBase + "trials = 0\n"), "bad.toml:9: tasks[1].trials: must be >= 1");
  EXPECT_NE(errorOf(kBase + "when = { method = \"c\" }\n").find("bad.toml:9: tasks[1].when.method: must name a level"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "when = { colour = \"c\" }\n").find("tasks[1].when.colour: no factor of that name"), std::string::npos);
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = 2\n[[tasks]]\ntask = \"juggling\"\n").find("bad.toml:4: tasks[1]: unknown task"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "settings = [\"nonsense=1\"]\n").find("bad.toml:9: tasks[1]"), std::string::npos);
  EXPECT_EQ(errorOf("id = \"x\"\nparticipants = 2\nseed = \"seven\"\n[[tasks]]\ntask = \"layer-index\"\n"),
            "bad.toml:3: seed: must be an integer");
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = [\n").find("bad.toml:"), std::string::npos);  // TOML syntax error
  EXPECT_EQ(errorOf("participants = 2\n[[tasks]]\ntask = \"layer-index\"\n").substr(0, 15), "bad.toml:1: id:");
  EXPECT_EQ(errorOf(kBase + "navigation = \"fly\"\n"), "bad.toml:9: tasks[1].navigation: navigation 'fly': expected none, orbit or walk");
  EXPECT_NE(errorOf(kBase + "navigation = \"orbit\"\n").find("bad.toml:9: tasks[1].navigation: only counting, pattern and target-discovery"),
            std::string::npos);
}

TEST(ExperimentFile, DesignConstraintsAreCheckedAgainstTheFile) {
  const std::string graeco = R"(id = "g"
participants = 3
counterbalancing = "graeco-latin"
[[factors]]
name = "a"
levels = ["1", "2", "3"]
[[factors]]
name = "b"
levels = ["1", "2"]
[[tasks]]
task = "layer-index"
)";
  EXPECT_EQ(errorOf(graeco),
            "bad.toml:3: counterbalancing: graeco-latin needs exactly two within factors with the same number of levels");
  const std::string six = R"(id = "g"
participants = 6
counterbalancing = "graeco-latin"
[[factors]]
name = "a"
levels = ["1", "2", "3", "4", "5", "6"]
[[factors]]
name = "b"
levels = ["1", "2", "3", "4", "5", "6"]
[[tasks]]
task = "layer-index"
)";
  EXPECT_NE(errorOf(six).find("no Graeco-Latin square of order 6 exists"), std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"speed\"]\n").find("bad.toml:10: analysis[1].dv: 'speed' is not one of"),
            std::string::npos);
  // tests = ["mixed"]: the formula is parsed and must model one of the analysis's dv; the correction is p.adjust's.
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"rt\"]\ntests = [\"glmm\"]\n").find("'glmm' is not one of anova, t-tests, rank-tests, mixed"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"rt\"]\ntests = [\"mixed\"]\nformula = \"rt ~ method\"\n")
                .find("bad.toml:12: analysis[1].formula: formula 'rt ~ method': no random-effects term"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"rt\"]\nformula = \"correct ~ method + (1 | participant)\"\n")
                .find("analysis[1].formula: the response 'correct' is not one of the analysis's dv"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[analysis]]\ndv = [\"rt\"]\ncorrection = \"tukey\"\n")
                .find("bad.toml:11: analysis[1].correction: 'tukey' is not a p-value adjustment"),
            std::string::npos);
  EXPECT_NE(errorOf(kBase + "[[factors]]\nname = \"method\"\nlevels = [\"c\", \"d\"]\n").find("factor 'method' is defined twice"),
            std::string::npos);
  EXPECT_NE(errorOf("id = \"x\"\nparticipants = 1\nblock_tasks = \"by-position\"\n[[tasks]]\ntask = \"layer-index\"\n[[tasks]]\n"
                    "task = \"counting\"\n")
                .find("\"by-position\" needs one task per block: 1 blocks but 2 tasks"),
            std::string::npos);
}

TEST(ExperimentFile, SessionFlowKeysAreCheckedWithFileLineAndField) {
  EXPECT_EQ(errorOf(kBase + "[[info]]\nid = \"age\"\ntext = \"Age\"\nkind = \"colour\"\n"),
            "bad.toml:12: info[1].kind: expected likert, choice, number or text, got 'colour'");
  EXPECT_EQ(errorOf(kBase + "[[info]]\nid = \"hand\"\ntext = \"Hand\"\nkind = \"choice\"\noptions = [\"left\"]\n"),
            "bad.toml:13: info[1].options: a choice needs at least two options");
  EXPECT_EQ(errorOf(kBase + "[breaks]\nevery = 2\nunit = \"minutes\"\n"),
            "bad.toml:11: breaks.unit: expected \"trials\" or \"blocks\", got 'minutes'");
  EXPECT_EQ(errorOf(kBase + "[breaks]\nevery = 0\n"), "bad.toml:10: breaks.every: must be >= 1");
  EXPECT_EQ(errorOf(kBase + "[consent]\naccept = \"yes\"\n"), "bad.toml:9: consent.text: missing (a string is required)");
  EXPECT_EQ(errorOf(kBase + "[training]\nfeedback = \"yes\"\n"), "bad.toml:10: training.feedback: must be true or false");
  EXPECT_EQ(errorOf(kBase + "[[questionnaires]]\nid = \"q\"\nitems = [{ id = \"n\", text = \"N\", kind = \"number\", min = 5, max = 1 }]\n"),
            "bad.toml:11: questionnaires[1].items[1].min: must not exceed max");
  const Experiment flow = readExperimentFile(tlab::testing::studyData("flow.toml"));
  EXPECT_EQ(flow.participantTitle, "A study of transparent shapes");
  ASSERT_TRUE(flow.consent.has_value());
  ASSERT_EQ(flow.info.size(), 4u);  // standard_info (age, gender, vision) and handedness
  EXPECT_EQ(flow.info[3].options.size(), 3u);
  EXPECT_TRUE(flow.trainingFeedback);
  EXPECT_EQ(flow.breaks.every, 2);
  EXPECT_EQ(flow.debrief.completionCode, "C0DE42");
  ASSERT_EQ(flow.questionnaires.at(0).items.size(), 4u);
  EXPECT_EQ(flow.questionnaires[0].items[1].kind, FieldKind::Choice);
  EXPECT_EQ(flow.questionnaires[0].items[0].points, 5);
}

TEST(FormField, AnswersAreCheckedByKind) {
  FormField likert{"ease", "Easy?", FieldKind::Likert};
  likert.points = 5;
  EXPECT_EQ(fieldError(likert, "5"), "");
  EXPECT_NE(fieldError(likert, "6"), "");
  EXPECT_NE(fieldError(likert, ""), "");
  FormField age{"age", "Age", FieldKind::Number};
  age.minimum = 16;
  age.maximum = 120;
  age.integer = true;
  EXPECT_EQ(fieldError(age, "34"), "");
  EXPECT_EQ(fieldError(age, "34.5"), "a whole number is required");
  EXPECT_EQ(fieldError(age, "12"), "a number from 16 to 120 is required");
  EXPECT_EQ(fieldError(age, "abc"), "'abc' is not a number");
  EXPECT_EQ(fieldNumber(age, "34").value_or(-1), 34.0);
  FormField choice{"hand", "Hand", FieldKind::Choice};
  choice.options = {"left", "right"};
  EXPECT_EQ(fieldError(choice, "right"), "");
  EXPECT_EQ(fieldNumber(choice, "right").value_or(-1), 2.0);
  EXPECT_NE(fieldError(choice, "both"), "");
  FormField text{"notes", "Notes", FieldKind::Text};
  text.required = false;
  EXPECT_EQ(fieldError(text, ""), "");
  EXPECT_FALSE(fieldNumber(text, "anything").has_value());
}
