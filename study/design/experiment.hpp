#pragma once
// An experiment as the experiment file describes it: factors and their levels (each level may set
// the scene, the style, style settings or the camera of the stimulus), the counterbalancing of the
// condition blocks, the tasks run in each block, training, instructions, questionnaires, the
// analysis plan and the simulated observer's parameters. Built by ExperimentFile; pure data.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/design/navigation.hpp"
#include "study/design/participant_texts.hpp"

namespace tlab::study {

enum class FactorKind { Within, Between };

struct Level {
  std::string name;
  std::optional<std::string> scene;   // scene source (builtin:NAME?..., glTF path); "{trial}" is replaced
  std::optional<std::string> style;   // renderer style
  std::optional<std::string> camera;  // "eye=... target=..." (tlab render --camera)
  std::vector<std::string> renderSettings;  // style key=value
  // Images from another renderer instead of tlab's picture: a PNG path template (absolute once
  // read, written relative to the experiment file) with {FACTOR} placeholders for any factor's
  // level name and {trial}; tlab keeps the scene, camera, size and ground truth of the cell.
  std::optional<std::string> images;
};

struct Factor {
  std::string name;
  FactorKind kind = FactorKind::Within;
  std::vector<Level> levels;
  int levelIndex(const std::string& levelName) const;  // -1 if none
};

// How the order of the condition blocks varies between participants.
enum class Counterbalancing {
  Fixed,        // every participant: the conditions in factor order
  LatinSquare,  // cyclic Latin square over the within conditions
  Williams,     // balanced Latin square (first-order carry-over balanced; doubled for odd n)
  GraecoLatin,  // two within factors with n levels each at once: n blocks, each level of each once
  Permutation,  // every order of the within conditions
  Random,       // a seeded random order per participant slot
};
const char* counterbalancingName(Counterbalancing c);

// Which tasks a block runs.
enum class BlockTasks {
  All,         // every task whose `when` matches the block's condition, in task order
  ByPosition,  // block k runs task k (Carnecky Sec. 8: tasks in a fixed order, one per block)
};

struct TaskSpec {
  std::string id;        // name in the database and reports ("T1", "layer-index")
  std::string task;      // tasks/ module name
  int trials = 1;        // trials per block (each on its own scene instance when the scene uses {trial})
  int questions = 1;     // questions (probe sets) per trial
  int trainingTrials = 0;
  double timeLimitSeconds = 120.0;           // per question
  std::optional<double> trialTimeLimitSeconds;  // for all questions of a trial together (Carnecky)
  std::vector<std::string> settings;         // task settings key=value
  std::map<std::string, std::string> when;   // factor → level; empty: every block
  std::optional<std::string> scene;          // overrides the condition's scene for this task ("{trial}" replaced)
  std::string instructions;
  // Interactive trials (Elmqvist): the window renders the scene live and the participant orbits
  // (ABSTRACT) or walks (WALKTHROUGH); simulated observers see the start view.
  Navigation navigation = Navigation::None;
  std::string navigationSource;  // "file:line" of the navigation field (online runs refuse walking)
  std::string settingsSource;    // "file:line: tasks[N].settings" (or the task's table): probe failures name it
  std::string trainingSource;    // "file:line: tasks[N].training_trials": a training stimulus shown in a test trial
};

// One question of a form: a participant-information field or a questionnaire item.
enum class FieldKind { Likert, Choice, Number, Text };
const char* fieldKindName(FieldKind kind);

struct FormField {
  std::string id;
  std::string text;
  FieldKind kind = FieldKind::Likert;
  int points = 7;                    // Likert: 1..points
  std::string lowAnchor = "strongly disagree";
  std::string highAnchor = "strongly agree";
  std::vector<std::string> options{};  // Choice
  double minimum = 0.0;              // Number
  double maximum = 1e9;
  bool integer = false;              // Number: whole numbers only
  bool required = true;              // Choice/Number/Text: an empty answer is refused
};

struct Questionnaire {
  std::string id;
  std::string when = "end";  // "start", "end" or "after-block"
  std::string title;         // shown above the items ("" → "Questionnaire")
  std::vector<FormField> items;
};

// [consent]: shown before anything else; a decline ends the session and stores only the decline.
struct ConsentSpec {
  std::string text;
  std::string accept = "I agree to take part";
  std::string decline = "I do not agree";
};

// [breaks]: a pause screen every N test trials or blocks, at least min_seconds long.
struct BreakSpec {
  int every = 0;          // 0: no breaks
  bool blocks = false;    // count blocks rather than trials
  double minSeconds = 0.0;
  std::string text = "Take a short break. Continue when you are ready.";
};

// [debrief]: the last screen; an optional completion code (Prolific and the like) is shown on it.
struct DebriefSpec {
  std::string text = "Thank you. The session is complete.";
  std::string completionCode;
};

// [online]: how `tlab serve` runs the study in a browser (Prolific and the like).
struct OnlineSpec {
  std::string participantParameter = "pid";  // the URL parameter carrying the participant id ("PROLIFIC_PID")
  std::string studyParameter;                // stored with the session when given ("STUDY_ID")
  std::string sessionParameter;              // ("SESSION_ID")
  double timeoutMinutes = 60.0;              // no request for this long: the participant is dropped, the slot freed
  bool live = true;                          // orbit and walk tasks rendered live by the server (false: orbit as a turntable)
  std::string frames = "png";                // how live frames are sent: "png" (lossless) or "jpeg" (lossy, logged with each frame)
  int jpegQuality = 90;                      // frames = "jpeg": libjpeg's quality, 1..100
  int turntableAzimuths = 36;                // orbit tasks with live = false: pre-rendered views around the target ...
  int turntableElevations = 5;               // ... at this many elevations
  double turntableElevationDegrees = 60.0;   // spread of the elevations (centred on the start view)
  std::string completionUrl;                 // the debrief links here (Prolific's completion URL)
  bool sizeCalibration = false;              // the credit-card screen that measures pixels per centimetre
  bool calibrationNoCard = false;            // the calibration offers "I have no card" (stored as such)
  // How big a stimulus is shown: "native" (whole device pixels, an integer upscale to at least its
  // CSS size), "css" (its size in CSS px) or "cm" (stimulusCm wide; needs the size calibration).
  std::string stimulusSize = "native";
  double stimulusCm = 0.0;
  std::vector<std::string> devices = {"desktop"};  // which devices may take part: desktop, tablet, phone
};

struct AnalysisSpec {
  std::string title;
  std::vector<std::string> tasks;  // task ids to include; empty: all
  std::vector<std::string> dependentVariables;  // columns of the trial table: correct, score, rt, error, ...
  std::vector<std::string> within;
  std::vector<std::string> between;
  std::vector<std::string> tests = {"anova", "t-tests", "rank-tests"};  // and "mixed"
  double alpha = 0.05;
  // tests = ["mixed"]: the lme4 formula of the mixed model of the dependent variable it names
  // (empty: correct as a binomial GLMM, rt as an LMM on log(rt), others as an LMM, with the
  // factors as fixed effects and (1 | participant) + (1 | stimulus)).
  std::string formula;
  std::string correction = "none";  // p adjustment of the pairwise tests: holm, bonferroni, hochberg, BH, BY, none
};

// The simulated observer (study/run/simulated_observer.hpp documents every parameter).
struct ObserverParams {
  double contrastReference = 0.15;   // local RMS contrast at which a probe counts as fully visible
  double sensitivity = 4.0;          // slope of the logistic in visibility
  double threshold = 0.35;           // visibility giving half the above-chance accuracy
  double skillSpread = 0.25;         // sd of the per-participant log skill
  double lapse = 0.03;               // probability of a random answer
  double layerPenalty = 0.15;        // layer-index: visibility lost per layer behind the first
  double baseSeconds = 6.0;          // median response time at full visibility
  double slowSeconds = 12.0;         // added median time at zero visibility
  double rtSigma = 0.35;             // lognormal sd of response times
  double giveUpShare = 0.02;         // probability of no answer (missing)
  double gaugeDegrees = 8.0;         // gauge figure: angular sd (degrees) of a seen normal at full visibility
  double gaugeGrowth = 3.0;          // gauge figure: the sd grows by this factor times (1 − visibility)
};

struct Stimulus {
  std::string scene = "builtin:open-cylinders";
  std::string style = "constant";
  std::string camera;
  std::vector<std::string> renderSettings;
  int width = 512;
  int height = 512;
};

// A style file the experiment names (style = "styles/mine.glsl", relative to the experiment
// file): as written, the absolute path it was found at (what Level/Stimulus style then hold), and
// the SHA-256 of its text, which is part of the design's identity (editing the style file makes a
// new experiment version). Recorded in the stored text as "# tlab style file WRITTEN = PATH sha256 HEX".
struct StyleFileUse {
  std::string written;
  std::string path;
  std::string sha256;
};

struct Experiment {
  std::string path;         // file it was read from
  std::string text;         // the file's text, stored in the database (with the style files' identities appended)
  std::vector<StyleFileUse> styleFiles;
  std::string id;
  std::string title;             // for the researcher (reports); never shown to participants
  std::string participantTitle;  // shown on the participant's screens ("" → "Welcome")
  std::uint64_t seed = 1;
  int participants = 1;
  std::vector<Factor> factors;
  Counterbalancing counterbalancing = Counterbalancing::Fixed;
  BlockTasks blockTasks = BlockTasks::All;
  Stimulus stimulus;
  std::vector<TaskSpec> tasks;
  std::string welcome;
  std::optional<ConsentSpec> consent;
  std::vector<FormField> info;     // [[info]]: participant information (age, vision, ...)
  bool trainingFeedback = false;   // [training] feedback = true
  BreakSpec breaks;
  DebriefSpec debrief;
  OnlineSpec online;
  std::vector<Questionnaire> questionnaires;
  // Every word participants see: the language's table (language = "de") with [text]'s overrides.
  ParticipantTexts texts;
  std::string languageSource;  // "file:line: language" (or the file alone when it sets none), for tlab design's warnings
  std::vector<AnalysisSpec> analyses;
  ObserverParams observer;

  std::vector<const Factor*> withinFactors() const;
  std::vector<const Factor*> betweenFactors() const;
  const Factor* factor(const std::string& name) const;
  const TaskSpec* task(const std::string& id) const;
};

}  // namespace tlab::study
