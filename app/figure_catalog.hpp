#pragma once
// The seeds' key figures as tlab renders (`tlab figures`): per figure the paper, the figure it
// re-draws, what it shows, and the exact `tlab render` arguments with the papers' parameters.
// Data only; cmd_figures.cpp renders them.
#include <string>
#include <vector>

namespace tlab::app {

struct FigureSpec {
  std::string id;        // file name without .png
  std::string paper;     // "Carnecky et al. 2013"
  std::string figure;    // "Fig. 9 (a)"
  std::string shows;     // one line: what the figure shows and with which parameters
  std::string scene;
  std::string style;
  std::vector<std::string> settings;  // key=value, as --set
  std::string camera{};               // --camera, empty: the scene's own
  std::string renderer = "buffer";    // buffer | peel
};

const std::vector<FigureSpec>& figureCatalog();

// The exact command that renders `f` at `size` into `output`.
std::string figureCommand(const FigureSpec& f, const std::string& size, const std::string& output);

}  // namespace tlab::app
