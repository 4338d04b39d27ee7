#pragma once
// What `tlab replay` writes of a replayed trial: the frames as PNG files (frame-000000.png, … in
// the order shown), a video of them at their logged times (ffmpeg, Debian's, run as a subprocess
// with the concat demuxer and each frame's duration), and an HTML page with the frames, the input
// that moved each, its time, its check and the answer given.
#include <filesystem>
#include <string>
#include <vector>

#include "study/replay/logged_trial.hpp"
#include "study/replay/trial_replay.hpp"

namespace tlab::study {

// "frame-000042.png": the file of the i-th frame shown.
std::string frameFileName(std::size_t i);

// How long frame i stayed on screen, in seconds: until the next frame of the same showing; the
// last frame of a showing until the answer when it was given in that showing, else 1 s.
double shownSeconds(const LoggedTrial& trial, std::size_t i);

// The ffmpeg concat list of the frames in `folder` with their durations (the last one repeated,
// as the concat demuxer needs to keep its duration).
std::string concatList(const LoggedTrial& trial, const std::filesystem::path& folder);

// Runs ffmpeg on the frames in `folder` (written as frameFileName names them) to `output`
// (.webm: VP9, .mp4: H.264, otherwise ffmpeg's choice for the extension). Throws with one line when
// ffmpeg is missing or fails (its last message).
void writeReplayVideo(const LoggedTrial& trial, const std::filesystem::path& folder, const std::string& output);

// The replay page; `framesFolder` is where the frames lie, relative to the page.
std::string replayPage(const LoggedTrial& trial, const ReplayCheck& check, const std::string& framesFolder);

// The folder beside a replay page that holds its frames: replay.html → replay-frames.
std::filesystem::path pageFramesFolder(const std::filesystem::path& page);

// Renders the trial again (replayTrial) and writes every frame as a PNG file into each of
// `frameFolders` (created); the check of every frame.
ReplayCheck replayIntoFolders(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                              const std::vector<std::filesystem::path>& frameFolders);

// Renders the trial again and writes its page at `page` with the frames beside it (pageFramesFolder);
// the check of every frame. What `tlab replay --html` and `tlab report --replays` write.
ReplayCheck writeReplayPage(const LoggedTrial& trial, const std::vector<render::BuiltinSceneSpec>& catalog, const ReplayRenderer& self,
                            const std::filesystem::path& page);

}  // namespace tlab::study
