// Live views of tlab serve end to end over HTTP (issue #30), as the participant page and as an
// attacker would use POST /api/<token>/view: frames only for the live trial on show, each PNG's
// pixels the SHA-256 the server logs, input refused unless finite and bounded, the eye kept within
// the scene's bounds however far one walks, nothing after the trial, and every frame sent stored
// as a "frame" event of its trial.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_JPEG  // the JPEG frames as a browser decodes them
#include <stb/stb_image.h>

#include "core/png_file.hpp"
#include "renderer/scene/scene_source.hpp"
#include "study/design/scene_catalog.hpp"
#include "study/run/frame_log.hpp"
#include "study/serve/live_frames.hpp"
#include "tests/study/serve_test_client.hpp"
#include "tests/study/served_study.hpp"

namespace tlab::testing {
namespace {

using nlohmann::json;

struct Frame {
  int status = 0;
  int index = -1;
  std::string sha256;  // the server's header
  std::string pixels;  // framePixelsSha256 of the PNG as decoded here
  std::string body;
};

class ServeLive : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    db_ = (dir_ / "study.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Frame view(httplib::Client& http, const std::string& token, const json& body) {
    const auto r = http.Post(("/api/" + token + "/view").c_str(), body.dump(), "application/json");
    if (!r) throw std::runtime_error("no reply to the view request");
    Frame f{r->status, -1, r->get_header_value("X-Frame-Sha256"), "", r->body};
    if (r->status != 200) return f;
    f.index = std::stoi(r->get_header_value("X-Frame-Index"));
    const auto png = dir_ / "frame.png";
    std::ofstream(png, std::ios::binary) << r->body;
    const auto image = core::readPngFile(png.string());
    if (!image) throw std::runtime_error("the frame is not a PNG");
    f.pixels = study::framePixelsSha256(study::Canvas(*image));
    return f;
  }

  // The display report, then on through the messages to the first trial's screen.
  static json firstTrial(PageClient& page, const std::string& token) {
    json screen = page.api(token, "display", display()).body;
    while (screen["kind"] != "trial") screen = page.api(token, "reply", continueReply(screen)).body;
    return screen;
  }

  // Two participants explore both trials of live_online.toml with their requests interleaved, on
  // `renderers` LiveRenderers; every trial is replayed.
  void exploreInTurnAndReplay(int renderers) {
    ServedStudy server(studyData("live_online.toml"), db_, dir_, 0, {"--live-renderers", std::to_string(renderers)});
    PageClient page(server.port());
    httplib::Client http("127.0.0.1", server.port());
    http.set_read_timeout(120, 0);
    std::vector<std::string> tokens;
    std::vector<json> screens;
    for (const char* pid : {"PROLIFIC_PID=p1", "PROLIFIC_PID=p2"}) {
      const auto [status, token] = page.arrive("live-online", pid);
      ASSERT_EQ(status, 303);
      tokens.push_back(token);
      screens.push_back(firstTrial(page, token));
    }
    std::map<std::string, int> sentPerTrial;  // "p1 walk" → frames sent
    for (const char* task : {"walk", "orbit"}) {
      const std::vector<json> inputs = std::string(task) == "walk" ? std::vector<json>{json::object(), {{"dx", 12}}, {{"forward", 3}}, {{"dx", -7}, {"dy", 2}}}
                                                                   : std::vector<json>{json::object(), {{"dx", 9}, {"point", {0.3, 0.6}}}, {{"dy", -4}}};
      for (std::size_t step = 0; step < inputs.size(); ++step)
        for (std::size_t p = 0; p < tokens.size(); ++p) {  // p1, p2, p1, p2, ...: the shared view renders for both in turn
          ASSERT_EQ(screens[p]["live"]["navigation"], task) << screens[p].dump();
          json input = inputs[step];
          if (input.contains("point")) input["point"] = {0.3 + 0.4 * double(p), 0.6 - 0.4 * double(p)};  // each participant's lens elsewhere
          const Frame f = view(http, tokens[p], {{"seq", screens[p]["seq"]}, {"input", input}});
          ASSERT_EQ(f.status, 200) << f.body;
          EXPECT_EQ(f.index, int(step));
          EXPECT_EQ(f.pixels, f.sha256) << "the PNG holds exactly the pixels logged";
          ++sentPerTrial["p" + std::to_string(p + 1) + " " + task];
        }
      for (std::size_t p = 0; p < tokens.size(); ++p) {
        const int seq = screens[p]["seq"];
        json next = page.api(tokens[p], "reply", {{"seq", seq}, {"type", "answer"}, {"answer", 3}, {"rt_ms", 2000.0}}).body;
        while (next["kind"] == "message") next = page.api(tokens[p], "reply", continueReply(next)).body;
        screens[p] = next;
      }
    }
    for (std::size_t p = 0; p < tokens.size(); ++p) {
      const Walk rest = walk(page, tokens[p], screens[p]);
      ASSERT_EQ(rest.screens.back()["kind"], "end") << rest.screens.back().dump();
    }
    server.stop(SIGTERM);

    const auto events = exportedTable(db_, dir_, "events");
    const std::size_t kind = column(events, "kind"), who = column(events, "participant"), trial = column(events, "trial_sequence");
    std::map<std::pair<std::string, std::string>, int> logged;  // (participant, trial) → frames
    for (std::size_t i = 1; i < events.size(); ++i)
      if (events[i][kind] == study::kFrameEvent) ++logged[{events[i][who], events[i][trial]}];
    ASSERT_EQ(logged.size(), 4u);
    for (const auto& [at, n] : logged) {
      const CommandResult replay = runCommand(commandLine({TLAB_EXE, "replay", db_, "--participant", at.first, "--trial", at.second}));
      EXPECT_EQ(replay.exitCode, 0) << replay.out << replay.err;
      const std::string identical = std::to_string(n) + " of " + std::to_string(n) + " frames identical";
      EXPECT_NE(replay.out.find(identical), std::string::npos) << at.first << " trial " << at.second << ": " << replay.out << replay.err;
    }
    std::map<std::string, int> perParticipant;
    for (const auto& [at, n] : logged) perParticipant[at.first] += n;
    EXPECT_EQ(perParticipant["p1"], sentPerTrial["p1 walk"] + sentPerTrial["p1 orbit"]) << "every frame sent is logged";
    EXPECT_EQ(perParticipant["p2"], sentPerTrial["p2 walk"] + sentPerTrial["p2 orbit"]);
  }

  std::filesystem::path dir_;
  std::string db_;
};

TEST_F(ServeLive, FramesComeOnlyFromTheTrialOnShowWithinItsBoundsAndEveryOneIsLogged) {
  ServedStudy server(studyData("live_online.toml"), db_, dir_);
  PageClient page(server.port());
  const auto [status, token] = page.arrive("live-online", "PROLIFIC_PID=p1");
  ASSERT_EQ(status, 303);
  httplib::Client http("127.0.0.1", server.port());
  http.set_read_timeout(60, 0);
  json screen = page.api(token, "display", display()).body;
  ASSERT_EQ(screen["kind"], "message") << screen.dump();
  EXPECT_EQ(view(http, token, {{"seq", screen["seq"]}, {"input", json::object()}}).status, 409) << "a message is not a live trial";
  while (screen["kind"] != "trial") screen = page.api(token, "reply", continueReply(screen)).body;
  ASSERT_TRUE(screen.contains("live")) << screen.dump();
  EXPECT_EQ(screen["live"]["navigation"], "walk");
  EXPECT_FALSE(screen.contains("turntable"));
  const int seq = screen["seq"];
  ASSERT_EQ(page.api(token, "reply", {{"seq", seq}, {"type", "onset"}, {"painted_ms", 10.5}}).status, 200);

  std::vector<Frame> sent;
  sent.push_back(view(http, token, {{"seq", seq}}));  // no input: the start view
  sent.push_back(view(http, token, {{"seq", seq}, {"input", {{"dx", 30}}}}));
  for (const Frame& f : sent) {
    ASSERT_EQ(f.status, 200) << f.body;
    EXPECT_EQ(f.pixels, f.sha256) << "the PNG holds exactly the pixels whose SHA-256 is logged";
  }
  EXPECT_EQ(sent[0].index, 0);
  EXPECT_EQ(sent[1].index, 1);
  EXPECT_NE(sent[0].sha256, sent[1].sha256) << "the drag turned the view";

  // What no page sends is refused, and neither rendered nor logged.
  for (const json& bad : {json{{"seq", seq}, {"input", {{"dx", "30"}}}}, json{{"seq", seq}, {"input", {{"dx", 1e6}}}},
                          json{{"seq", seq}, {"input", {{"forward", 1.5}}}}, json{{"seq", seq}, {"input", {{"point", {2, 0}}}}},
                          json{{"seq", seq}, {"input", {{"camera", "eye=0,0,0 target=0,0,1"}}}}, json{{"input", json::object()}},
                          json{{"seq", seq}, {"input", {1, 2}}}})
    EXPECT_EQ(view(http, token, bad).status, 400) << bad.dump();
  EXPECT_EQ(view(http, token, {{"seq", seq + 1}, {"input", {{"dx", 5}}}}).status, 409) << "a screen not on show";
  EXPECT_EQ(view(http, "0000000000000000000000000000000000000000000000000000000000000000", {{"seq", seq}}).status, 404);

  // Walking on and on without collision: the eye stops at the bounds of the scene.
  for (int i = 0; i < 30; ++i) {
    sent.push_back(view(http, token, {{"seq", seq}, {"input", {{"forward", 40}}}}));
    ASSERT_EQ(sent.back().status, 200) << sent.back().body;
  }
  json answered = page.api(token, "reply", {{"seq", seq}, {"type", "answer"}, {"answer", 3}, {"rt_ms", 2000.0}}).body;
  EXPECT_EQ(view(http, token, {{"seq", seq}, {"input", {{"dx", 5}}}}).status, 409) << "the trial has ended";
  while (answered["kind"] == "message") answered = page.api(token, "reply", continueReply(answered)).body;  // the orbit task's instructions
  ASSERT_EQ(answered["kind"], "trial") << answered.dump();  // the orbit trial
  ASSERT_EQ(answered["live"]["navigation"], "orbit");
  EXPECT_TRUE(answered["live"]["lens"].get<bool>()) << "the dynamic style in active mode: its lens follows the cursor";
  const Frame orbit = view(http, token, {{"seq", answered["seq"]}, {"input", {{"point", {0.25, 0.5}}}}});
  ASSERT_EQ(orbit.status, 200) << orbit.body;
  EXPECT_EQ(orbit.index, 0) << "each trial counts its own frames";
  EXPECT_EQ(orbit.pixels, orbit.sha256);
  const Walk rest = walk(page, token, answered);
  ASSERT_EQ(rest.screens.back()["kind"], "end") << rest.screens.back().dump();
  server.stop(SIGTERM);

  const auto events = exportedTable(db_, dir_, "events");
  const std::size_t kind = column(events, "kind"), detail = column(events, "detail"), trial = column(events, "trial_sequence");
  std::map<std::string, std::vector<study::LiveFrame>> frames;  // by trial
  for (std::size_t i = 1; i < events.size(); ++i)
    if (events[i][kind] == study::kFrameEvent) frames[events[i][trial]].push_back(study::parseFrameJson(events[i][detail]));
  ASSERT_EQ(frames.size(), 2u);
  const auto& walked = frames.begin()->second;
  ASSERT_EQ(walked.size(), sent.size()) << "every frame sent is stored, nothing refused is";
  for (std::size_t i = 0; i < walked.size(); ++i) {
    EXPECT_EQ(walked[i].index, int(i));
    EXPECT_EQ(walked[i].sha256, sent[i].sha256);
    EXPECT_FALSE(walked[i].lens) << "the walk trial's style has no lens";
    EXPECT_EQ(walked[i].encoding, "png") << "lossless unless the experiment chooses otherwise";
  }
  EXPECT_EQ(walked[0].input, "start");
  EXPECT_EQ(walked[1].input, "drag 30,0");
  EXPECT_EQ(walked[2].input, "key 40,0");
  const auto scene = std::make_shared<const render::Scene>(render::loadScene("builtin:walkthrough?seed=1", study::sceneCatalog()));
  const study::LiveTrial bounds{scene, {}, study::Navigation::Walk, walked[0].camera};
  for (const auto& f : walked) EXPECT_TRUE(study::withinLiveBounds(bounds, f.camera)) << render::cameraText(f.camera);
  EXPECT_EQ(render::cameraText(walked[walked.size() - 1].camera), render::cameraText(walked[walked.size() - 2].camera))
      << "at the bounds, walking on no longer moves the eye";
  const auto& orbited = frames.rbegin()->second;
  ASSERT_EQ(orbited.size(), 1u);
  ASSERT_TRUE(orbited[0].lens);
  EXPECT_EQ(*orbited[0].lens, glm::vec2(0.25f, 0.5f));
  EXPECT_EQ(orbited[0].input, "point 0.25,0.5");
}

// The renderers of live trials are made before a participant asks (issue #30): a constant trial's
// view is shared by every session and its start frame rendered while the study is prepared; the
// dynamic trial's first session takes a spare view whose start frame is rendered. Two participants
// explore both trials with their requests interleaved, and every frame they were sent — the start
// frames rendered beforehand, the shared view's frames of both — is what a fresh renderer makes:
// `tlab replay` renders each trial again on its own and finds N of N frames identical.
TEST_F(ServeLive, PreparedAndSharedRenderersServeWhatAFreshRendererMakes) { exploreInTurnAndReplay(1); }

// Two LiveRenderers (tlab serve --live-renderers 2, each its own GL context): the participants' frames
// come from both, each session's from one, and are what a fresh renderer makes.
TEST_F(ServeLive, TwoLiveRenderersServeWhatAFreshRendererMakes) { exploreInTurnAndReplay(2); }

// [online] frames = "jpeg" (issue #30 §1: a lossy encoding may be chosen and is logged): the frames
// come as JPEGs, each frame event says so, its SHA-256 stays that of the rendered pixels — `tlab
// replay` finds N of N frames identical — and each JPEG shows those pixels up to the loss.
TEST_F(ServeLive, JpegFramesAreSentLoggedWithTheirEncodingAndReplayedExactly) {
  const auto experiment = dir_ / "live_jpeg.toml";
  std::ofstream(experiment) << readText(studyData("live_online.toml")) << "frames = \"jpeg\"\njpeg_quality = 85\n";  // [online] is the last table
  ServedStudy server(experiment.string(), db_, dir_);
  PageClient page(server.port());
  const auto [status, token] = page.arrive("live-online", "PROLIFIC_PID=j1");
  ASSERT_EQ(status, 303);
  const json screen = firstTrial(page, token);
  httplib::Client http("127.0.0.1", server.port());
  http.set_read_timeout(120, 0);
  std::vector<std::string> jpegs;
  for (const json& input : {json::object(), json{{"dx", 20}}, json{{"forward", 4}}}) {
    const auto r = http.Post(("/api/" + token + "/view").c_str(), json{{"seq", screen["seq"]}, {"input", input}}.dump(), "application/json");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/jpeg");
    EXPECT_EQ(r->get_header_value("X-Frame-Encoding"), "jpeg quality=85");
    jpegs.push_back(r->body);
  }
  json next = page.api(token, "reply", {{"seq", screen["seq"]}, {"type", "answer"}, {"answer", 3}, {"rt_ms", 2000.0}}).body;
  const Walk rest = walk(page, token, next);
  ASSERT_EQ(rest.screens.back()["kind"], "end") << rest.screens.back().dump();
  server.stop(SIGTERM);

  const auto events = exportedTable(db_, dir_, "events");
  const std::size_t kind = column(events, "kind"), detail = column(events, "detail"), trial = column(events, "trial_sequence");
  std::vector<study::LiveFrame> walked;
  std::string sequence;
  for (std::size_t i = 1; i < events.size(); ++i)
    if (events[i][kind] == study::kFrameEvent && (sequence.empty() || events[i][trial] == sequence)) {
      sequence = events[i][trial];
      walked.push_back(study::parseFrameJson(events[i][detail]));
    }
  ASSERT_EQ(walked.size(), jpegs.size());
  for (const auto& f : walked) EXPECT_EQ(f.encoding, "jpeg quality=85");
  const auto replayed = dir_ / "replayed";
  const CommandResult replay = runCommand(commandLine({TLAB_EXE, "replay", db_, "--participant", "j1", "--trial", sequence, "--frames", replayed.string()}));
  ASSERT_EQ(replay.exitCode, 0) << replay.out << replay.err;
  EXPECT_NE(replay.out.find("3 of 3 frames identical"), std::string::npos) << replay.out;
  for (std::size_t i = 0; i < jpegs.size(); ++i) {  // the JPEG shows the rendered frame, within its loss
    char name[32];
    std::snprintf(name, sizeof name, "frame-%06zu.png", i);
    const auto rendered = core::readPngFile((replayed / name).string());
    ASSERT_TRUE(rendered) << name;
    int w = 0, h = 0, n = 0;
    unsigned char* sent = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(jpegs[i].data()), int(jpegs[i].size()), &w, &h, &n, 3);
    ASSERT_NE(sent, nullptr) << "frame " << i << " is not a JPEG";
    ASSERT_EQ(w, rendered->width);
    ASSERT_EQ(h, rendered->height);
    double error = 0.0;
    for (int p = 0; p < w * h; ++p)
      for (int c = 0; c < 3; ++c) error += std::abs(double(sent[3 * p + c]) / 255.0 - double(rendered->pixels[std::size_t(p)][c]));
    stbi_image_free(sent);
    EXPECT_LT(error / (3.0 * w * h), 0.02) << "frame " << i << ": the mean difference of the JPEG from the rendered pixels";
    EXPECT_GT(error, 0.0) << "frame " << i << ": lossy, not the PNG's pixels";
  }
}

}  // namespace
}  // namespace tlab::testing
