#pragma once
// The participant page's files (study/serve/web/), embedded in tlab at build time
// (study/CMakeLists.txt): the page needs no CDN, no download and no file beside tlab.
#include <string_view>

namespace tlab::study {

// The text of web/<name> ("participant.html", "participant.js", "participant.css"); throws for others.
std::string_view webAsset(std::string_view name);

}  // namespace tlab::study
