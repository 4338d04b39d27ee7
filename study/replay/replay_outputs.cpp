#include "study/replay/replay_outputs.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "analysis/number_format.hpp"
#include "core/child_process.hpp"
#include "core/file_text.hpp"
#include "core/image.hpp"
#include "renderer/scene/camera.hpp"

namespace tlab::study {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> codecFor(const std::string& output) {
  const std::string ext = fs::path(output).extension().string();
  // Frames of odd size are padded by one pixel: 4:2:0 video needs even sizes.
  const std::vector<std::string> even = {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p"};
  std::vector<std::string> codec;
  if (ext == ".webm") codec = {"-c:v", "libvpx-vp9", "-crf", "4", "-b:v", "0", "-row-mt", "1"};
  else if (ext == ".mp4" || ext == ".mkv") codec = {"-c:v", "libx264", "-crf", "4", "-preset", "medium"};
  codec.insert(codec.end(), even.begin(), even.end());
  return codec;
}

std::string millis(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", seconds * 1000.0);
  return buf;
}

// The frames as the page's player reads them: file, time since the showing's first frame, duration.
nlohmann::json playerFrames(const LoggedTrial& trial, const std::string& folder) {
  nlohmann::json frames = nlohmann::json::array();
  std::int64_t start = 0;
  for (std::size_t i = 0; i < trial.frames.size(); ++i) {
    const LiveFrame& f = trial.frames[i].frame;
    if (f.index == 0 || i == 0) start = f.shownNs;
    frames.push_back({{"src", folder + "/" + frameFileName(i)}, {"t_ms", (f.shownNs - start) / 1e6}, {"ms", shownSeconds(trial, i) * 1000.0}});
  }
  return frames;
}

std::string answerText(const LoggedTrial& t) {
  if (!t.correct) return "no response stored";
  std::string s = t.answer ? "“" + *t.answer + "”" : "none (missing)";
  s += std::string(*t.correct ? ", correct" : ", not correct") + " (truth " + t.truth + ")";
  if (t.rtSeconds) s += ", " + millis(*t.rtSeconds) + " ms after the onset";
  return s;
}

std::string frameRows(const LoggedTrial& trial, const ReplayCheck& check) {
  using analysis::escapeHtml;
  std::string rows;
  std::int64_t start = 0;
  for (std::size_t i = 0; i < trial.frames.size(); ++i) {
    const LoggedFrame& lf = trial.frames[i];
    const LiveFrame& f = lf.frame;
    if (f.index == 0 || i == 0) start = f.shownNs;
    const FrameCheck& c = check.frames[i];
    char lens[64] = "";
    if (f.lens) std::snprintf(lens, sizeof lens, "%.4f, %.4f", f.lens->x, f.lens->y);
    rows += "<tr class=\"" + std::string(c.identical ? "same" : "differs") + "\" data-frame=\"" + std::to_string(i) + "\"><td>" +
            std::to_string(i) + "</td><td>" + std::to_string(lf.session) + " / " + std::to_string(f.index) + "</td><td>" +
            millis((f.shownNs - start) / 1e9) + "</td><td>" + millis(shownSeconds(trial, i)) + "</td><td>" + escapeHtml(f.input) +
            "</td><td class=\"camera\">" + escapeHtml(render::cameraText(f.camera)) + "</td><td>" + lens + "</td><td><code>" +
            f.sha256.substr(0, 12) + "</code></td><td>" +
            (c.identical ? std::string("identical") : "<b>differs</b>: replayed <code>" + c.replayedSha256.substr(0, 12) + "</code>; " + escapeHtml(c.why)) +
            "</td></tr>";
  }
  return rows;
}

constexpr const char* kPlayer = R"(<script>
const frames = JSON.parse(document.getElementById('frames').textContent);
const img = document.getElementById('picture'), slider = document.getElementById('slider'), label = document.getElementById('at');
let at = 0, timer = null;
function show(i) {
  at = i; img.src = frames[i].src; slider.value = i;
  label.textContent = 'frame ' + i + ' of ' + frames.length + ', ' + frames[i].t_ms.toFixed(1) + ' ms';
  document.querySelectorAll('tr.current').forEach(r => r.classList.remove('current'));
  const row = document.querySelector('tr[data-frame="' + i + '"]'); if (row) row.classList.add('current');
}
function play() {
  clearTimeout(timer);
  const step = () => { if (at + 1 < frames.length) { timer = setTimeout(() => { show(at + 1); step(); }, frames[at].ms); } };
  show(at + 1 < frames.length ? at : 0); step();
}
slider.max = frames.length - 1;
slider.oninput = () => { clearTimeout(timer); show(+slider.value); };
document.getElementById('play').onclick = play;
show(0);
</script>)";

}  // namespace

std::string frameFileName(std::size_t i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "frame-%06zu.png", i);
  return buf;
}

double shownSeconds(const LoggedTrial& trial, std::size_t i) {
  const LoggedFrame& f = trial.frames[i];
  const bool last = i + 1 == trial.frames.size() || trial.frames[i + 1].frame.index == 0;
  std::int64_t until = 0;
  if (!last) until = trial.frames[i + 1].frame.shownNs;
  else if (trial.responseNs > f.frame.shownNs && (i + 1 == trial.frames.size())) until = trial.responseNs;
  else until = f.frame.shownNs + 1'000'000'000;
  return std::max(1e-3, (until - f.frame.shownNs) / 1e9);
}

std::string concatList(const LoggedTrial& trial, const fs::path& folder) {
  std::string list = "ffconcat version 1.0\n";
  const auto entry = [&](std::size_t i) {
    std::string path = (folder / frameFileName(i)).string();
    std::string quoted;
    for (char c : path) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return "file '" + quoted + "'\n";
  };
  for (std::size_t i = 0; i < trial.frames.size(); ++i) {
    char duration[48];
    std::snprintf(duration, sizeof duration, "duration %.6f\n", shownSeconds(trial, i));
    list += entry(i) + duration;
  }
  return list + entry(trial.frames.size() - 1);
}

void writeReplayVideo(const LoggedTrial& trial, const fs::path& folder, const std::string& output) {
  // The frame list and ffmpeg's messages lie in the temporary folder while it runs, never among the frames.
  struct Scratch {
    fs::path list, log;
    ~Scratch() {
      std::error_code ignored;
      fs::remove(list, ignored);
      fs::remove(log, ignored);
    }
  } scratch;
  const std::string stem = "tlab-replay-" + std::to_string(::getpid());
  scratch.list = fs::temp_directory_path() / (stem + ".ffconcat");
  scratch.log = fs::temp_directory_path() / (stem + ".log");
  const fs::path &list = scratch.list, &log = scratch.log;
  {
    std::ofstream out(list, std::ios::binary);
    out << concatList(trial, fs::absolute(folder));
    if (!out) throw std::runtime_error(list.string() + ": cannot write the frame list for ffmpeg");
  }
  std::vector<std::string> argv = {"ffmpeg", "-nostdin", "-v", "error", "-y", "-f", "concat", "-safe", "0", "-i", list.string(), "-fps_mode", "vfr"};
  for (auto& a : codecFor(output)) argv.push_back(a);
  argv.push_back(output);
  const int status = core::runProgram(argv, log);
  if (status == 127) throw std::runtime_error("ffmpeg not found: install Debian's ffmpeg (scripts/setup.sh) to write " + output);
  if (status != 0) throw std::runtime_error("ffmpeg failed to write " + output + ": " + core::lastNonEmptyLine(core::readFileText(log.string()).value_or("")));
}

std::string replayPage(const LoggedTrial& trial, const ReplayCheck& check, const std::string& framesFolder) {
  using analysis::escapeHtml;
  const PlannedTrial& p = trial.plan;
  const std::string title = "Replay of " + trialName(trial);
  std::string frames = playerFrames(trial, framesFolder).dump();
  for (std::size_t at = 0; (at = frames.find("</", at)) != std::string::npos;) frames.replace(at, 2, "<\\/");
  std::string html = "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escapeHtml(title) + "</title><style>"
      "body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;"
      "padding:2px 6px;text-align:left}td.camera{font-family:monospace;font-size:11px}tr.differs{background:#fdd}tr.current{outline:2px solid #36c}"
      "#picture{image-rendering:pixelated;border:1px solid #888;width:" + std::to_string(std::max(p.stimulus.width, 320)) + "px}"
      ".verdict{font-size:1.2em;font-weight:bold}</style></head><body>";
  html += "<h1>" + escapeHtml(title) + "</h1><table class=\"facts\">";
  const auto fact = [&](const std::string& name, const std::string& value) {
    html += "<tr><th>" + name + "</th><td>" + escapeHtml(value) + "</td></tr>";
  };
  fact("experiment", trial.experimentId + " (" + trial.location + ")");
  fact("task", p.taskId + " (" + p.task + "), " + navigationName(p.navigation) + ", " + phaseName(p.phase) + " block " + std::to_string(p.block));
  fact("condition", p.condition);
  fact("stimulus", p.stimulus.text());
  fact("question", trial.question);
  fact("answer", answerText(trial));
  html += "</table><p class=\"verdict\" id=\"verdict\">" + escapeHtml(check.summary()) + "</p>";
  html += "<p><img id=\"picture\" alt=\"replayed frame\"></p><p><button id=\"play\">Play at the logged times</button> "
          "<input id=\"slider\" type=\"range\" min=\"0\" value=\"0\" style=\"width:360px\"> <span id=\"at\"></span></p>";
  html += "<h2>Frames</h2><p>Each frame as shown: its session and index there, its time since the showing's first frame, how long it "
          "stayed, the input that moved the view to it, the logged camera and lens, the logged SHA-256 of its pixels and whether the "
          "replay rendered the same pixels.</p><table id=\"frame-table\"><tr><th>#</th><th>session / index</th><th>shown at (ms)</th>"
          "<th>for (ms)</th><th>input</th><th>camera</th><th>lens</th><th>logged SHA-256</th><th>replay</th></tr>";
  html += frameRows(trial, check) + "</table>";
  html += "<script type=\"application/json\" id=\"frames\">" + frames + "</script>" + kPlayer + "</body></html>\n";
  return html;
}

fs::path pageFramesFolder(const fs::path& page) { return page.parent_path() / (page.stem().string() + "-frames"); }

ReplayCheck replayIntoFolders(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                              const std::vector<fs::path>& frameFolders) {
  for (const auto& folder : frameFolders) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw std::runtime_error(folder.string() + ": cannot create the folder (" + error.message() + ")");
  }
  return replayTrial(trial, catalog, self, [&](std::size_t i, const Canvas& picture, const FrameCheck&) {
    if (frameFolders.empty()) return;
    const auto png = core::encodePng(picture.toImage());
    for (const auto& folder : frameFolders) core::writeFileAtomically((folder / frameFileName(i)).string(), png);
  });
}

ReplayCheck writeReplayPage(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                            const fs::path& page) {
  const fs::path frames = pageFramesFolder(page);
  const ReplayCheck check = replayIntoFolders(trial, catalog, self, {frames});
  const std::string html = replayPage(trial, check, frames.filename().string());
  core::writeFileAtomically(page.string(), std::vector<std::uint8_t>(html.begin(), html.end()));
  return check;
}

}  // namespace tlab::study
