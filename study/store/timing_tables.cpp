#include "study/store/timing_tables.hpp"

#include <algorithm>
#include <map>

#include <nlohmann/json.hpp>

#include "analysis/number_format.hpp"

namespace tlab::study {

namespace {

std::size_t column(const DataTable& t, const std::string& name) {
  return std::size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
}

struct TimingSums {
  int trials = 0, late = 0;
  double swapSum = 0, swapMax = 0, frameSum = 0, frameMax = 0;
};

// A session's display JSON as stored; an empty object where none was stored or it does not parse.
nlohmann::json parsedDisplay(const std::string& json) {
  auto d = nlohmann::json::parse(json.empty() ? "{}" : json, nullptr, false);
  return d.is_object() ? d : nlohmann::json::object();
}

std::string displayText(const nlohmann::json& d) {
  if (d.empty()) return "(no display: simulated)";
  const auto size = [](const nlohmann::json& v) {
    return v.is_array() && v.size() == 2 ? std::to_string(v[0].get<int>()) + "x" + std::to_string(v[1].get<int>()) : std::string("?");
  };
  const auto window = d.value("window", nlohmann::json());
  if (!window.is_array() || window.size() != 2 || window[0].get<int>() == 0)
    return "no window (simulated); stimuli rendered by " + d.value("gl_renderer", std::string("?")) + " (" +
           d.value("gl_backend", std::string("?")) + ", GL " + d.value("gl_version", std::string("?")) + ")";
  const int hz = d.value("refresh_hz", 0);
  return d.value("gl_renderer", std::string("?")) + " (" + d.value("gl_vendor", std::string("?")) + ", GL " +
         d.value("gl_version", std::string("?")) + "); window " + size(d.value("window", nlohmann::json())) + ", framebuffer " +
         size(d.value("framebuffer", nlohmann::json())) + ", " + (hz > 0 ? std::to_string(hz) + " Hz" : "refresh unknown") +
         ", swap interval " + std::to_string(d.value("swap_interval", 0));
}

// The tlab (version+revision) that ran the session, from its display; "?" for sessions stored before
// it was recorded.
std::string tlabText(const nlohmann::json& d) { return d.value("tlab_version", std::string("?")); }

}  // namespace

analysis::TextTable sessionTimingTable(Store& store, const StoredExperiment& stored) {
  const DataTable sessions = store.exportTable(ExportTable::Sessions, stored.experiment);
  const DataTable trials = store.exportTable(ExportTable::Trials, stored.experiment);
  std::map<std::string, TimingSums> bySession;
  const std::size_t sessionColumn = column(trials, "session"), swap = column(trials, "onset_to_swap_ms"),
                    frame = column(trials, "onset_frame_ms"), late = column(trials, "late_frames");
  for (const auto& row : trials.rows) {
    if (row[sessionColumn].empty() || row[swap].empty()) continue;
    TimingSums& t = bySession[row[sessionColumn]];
    ++t.trials;
    t.swapSum += std::stod(row[swap]);
    t.swapMax = std::max(t.swapMax, std::stod(row[swap]));
    if (!row[frame].empty()) t.frameSum += std::stod(row[frame]), t.frameMax = std::max(t.frameMax, std::stod(row[frame]));
    if (!row[late].empty()) t.late += std::stoi(row[late]);
  }
  analysis::TextTable out;
  out.caption = "Timing per session (onset-to-swap: stimulus frame requested to buffer swap; onset frame: its swap-to-swap interval)";
  out.header = {"session", "participant", "mode", "tlab", "display", "timed trials", "onset-to-swap ms mean/max", "onset frame ms mean/max",
                "late frames"};
  const std::size_t id = column(sessions, "session"), who = column(sessions, "participant"), mode = column(sessions, "mode"),
                    display = column(sessions, "display");
  for (const auto& row : sessions.rows) {
    const auto it = bySession.find(row[id]);
    const TimingSums t = it == bySession.end() ? TimingSums{} : it->second;
    const auto pair = [&](double sum, double max) {
      return t.trials ? analysis::formatNumber(sum / t.trials, 3) + " / " + analysis::formatNumber(max, 3) : std::string("-");
    };
    const nlohmann::json shown = parsedDisplay(row[display]);
    out.rows.push_back({row[id], row[who], row[mode], tlabText(shown), displayText(shown), std::to_string(t.trials),
                        pair(t.swapSum, t.swapMax), pair(t.frameSum, t.frameMax), t.trials ? std::to_string(t.late) : "-"});
  }
  return out;
}

analysis::TextTable trialTimingTable(Store& store, const StoredExperiment& stored) {
  const DataTable trials = store.exportTable(ExportTable::Trials, stored.experiment);
  analysis::TextTable out;
  out.caption = "Timing per trial (window sessions)";
  out.header = {"participant", "session", "sequence", "phase", "onset_to_swap_ms", "onset_frame_ms", "late_frames", "rt_seconds"};
  const std::vector<std::size_t> columns = {column(trials, "participant"), column(trials, "session"), column(trials, "sequence"),
                                            column(trials, "phase"), column(trials, "onset_to_swap_ms"), column(trials, "onset_frame_ms"),
                                            column(trials, "late_frames"), column(trials, "rt_seconds")};
  for (const auto& row : trials.rows) {
    if (row[columns[4]].empty()) continue;  // simulated or unanswered: no frames
    std::vector<std::string> cells;
    for (const auto c : columns) cells.push_back(row[c]);
    for (const std::size_t k : {std::size_t(4), std::size_t(5), std::size_t(7)})
      if (!cells[k].empty()) cells[k] = analysis::formatNumber(std::stod(cells[k]), 4);
    out.rows.push_back(cells);
  }
  return out;
}

}  // namespace tlab::study
