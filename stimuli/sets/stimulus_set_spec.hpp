#pragma once
// What a stimulus set contains (parsed from a stimulus-set file): scenes, each with its views and
// probe sets, rendered in every listed style at one size. Every entry remembers the file line it
// came from, so later errors (unknown scene, no probes found) can name it.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "stimuli/sets/probe_source.hpp"

namespace tlab::stimuli {

// Where an entry was written: "set.toml:12" and the field path "scenes[1].source".
struct SourcePlace {
  std::string file;
  int line = 0;
  std::string field;
  std::string describe() const { return file + ":" + std::to_string(line) + ": " + field; }
};

struct StyleEntry {
  std::string name;  // a built-in style, or a style file's absolute path (written relative to the set file)
  std::map<std::string, std::string> settings;  // key → value (--set)
  std::string fileSha256;  // a style file's SHA-256 (empty for built-in styles)
  // Images from another renderer instead of tlab's picture ({ name = "theirs", images = "renders/
  // {scene}-{view}.png" }): the PNG path template as written (relative to the set file), with
  // {scene} and {view} standing for the scene's and the view's name; empty for a style.
  std::string images;
  SourcePlace place;
};

// A view: the scene's own camera orbited by azimuth/elevation, or a camera string on top of it.
struct ViewEntry {
  std::string name;                   // for {view} in an images path; "" → "v1", "v2", ... (viewName)
  double azimuthDegrees = 0.0;
  double elevationDegrees = 0.0;
  std::string camera;                 // "eye=... target=..." (optional)
  SourcePlace place;
};

struct ProbeSetEntry {
  ProbeSetSpec spec;
  SourcePlace place;
};

struct SceneEntry {
  std::string source;                 // builtin:NAME?... or a glTF path (relative to the set file)
  std::string name;                   // for {scene} in an images path; "" → the source's short name (sceneName)
  std::vector<ViewEntry> views;       // at least one
  std::vector<ProbeSetEntry> probeSets;  // may be empty: unlabelled stimuli
  SourcePlace place;
};

struct StimulusSetSpec {
  std::string name;
  std::string file;                   // the set file as given
  int width = 1024, height = 1024;
  std::uint64_t seed = 1;             // recorded; probe sets without a seed derive theirs from it
  std::vector<StyleEntry> styles;
  std::vector<SceneEntry> scenes;
  bool booklet = true;
  std::string questionPrefix;         // printed above every booklet question (instructions)
};

}  // namespace tlab::stimuli
