#pragma once
// Style files named by an experiment file (style = "styles/mine.glsl"): resolved relative to the
// experiment file, their SHA-256 read, and recorded in the experiment's stored text so a copy read
// back from the database names the same files with the same identities.
#include <toml++/toml.h>

#include "study/design/experiment.hpp"
#include "study/design/field_reader.hpp"

namespace tlab::study {

// Replaces every style that names a file (stimulus.style, each level's style) by its absolute
// path and fills e.styleFiles; appends the identities to e.text when the text does not record
// them yet. `readFiles`: whether a file that cannot be read fails (file:line: field).
void resolveStyleFiles(const FieldReader& r, const toml::table& root, Experiment& e, bool readFiles);

// The style's identity in the design fingerprint: the name of a built-in style, or
// "file sha256:HEX" for a style file (so moving the folder keeps the version, editing the file
// does not).
std::string styleIdentity(const Experiment& e, const std::string& style);

}  // namespace tlab::study
