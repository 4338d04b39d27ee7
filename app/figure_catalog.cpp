#include "app/figure_catalog.hpp"

namespace tlab::app {

namespace {

// Carnecky Fig. 9: the five configurations of its table — diffusion equation (9: spreading,
// 8: diffusion), profile modifier (10: exp, 11: pow), iterations n, λβ, λγ, p.
std::vector<FigureSpec> carnecky() {
  const std::string paper = "Carnecky et al. 2013 (seed 000)";
  const auto fig9 = [&](const char* letter, const char* shows, std::vector<std::string> s) {
    return FigureSpec{std::string("carnecky-fig9") + letter, paper, std::string("Fig. 9 (") + letter + ")", shows,
                      "builtin:pretzel", "smart", std::move(s)};
  };
  return {
      {"carnecky-fig1-constant", paper, "Fig. 1 / Fig. 2", "the rule of Fig. 1 broken: constant alpha on the open cylinders",
       "builtin:open-cylinders", "constant", {}},
      {"carnecky-fig1-smart", paper, "Fig. 1 / Fig. 2",
       "the rule of Fig. 1: the occluded cylinder hidden near the edge, more visible away from it", "builtin:open-cylinders",
       "smart", {}},
      fig9("a", "Eq. 9 spreading, n = 20, lambda_beta = 0.05, lambda_gamma = 0.1",
           {"spread=max", "iterations=20", "lambda_beta=0.05", "lambda_gamma=0.1", "modifier=none"}),
      fig9("b", "Eq. 9 spreading with the Eq. 10 modifier, p = 3",
           {"spread=max", "iterations=20", "lambda_beta=0.05", "lambda_gamma=0.1", "modifier=exp", "p=3"}),
      fig9("c", "Eq. 8 diffusion, n = 20, lambda_beta = 1, lambda_gamma = 0.1",
           {"spread=diffusion", "iterations=20", "lambda_beta=1", "lambda_gamma=0.1", "modifier=none"}),
      fig9("d", "Eq. 8 diffusion with the Eq. 11 modifier, p = 0.3",
           {"spread=diffusion", "iterations=20", "lambda_beta=1", "lambda_gamma=0.1", "modifier=pow", "p=0.3"}),
      fig9("e", "Eq. 8 diffusion, n = 100",
           {"spread=diffusion", "iterations=100", "lambda_beta=1", "lambda_gamma=0.1", "modifier=none"}),
      {"carnecky-fig10-smart", paper, "Fig. 10 (left)", "smart transparency on a complex stream surface", "builtin:toroid",
       "smart", {}},
      {"carnecky-fig10-constant", paper, "Fig. 10 (right)", "constant transparency on the same surface", "builtin:toroid",
       "constant", {}},
  };
}

std::vector<FigureSpec> iris() {
  const std::string paper = "Hummel et al. 2010, IRIS (seed 003)";
  return {
      {"iris-fig1-opaque-stripes", paper, "Fig. 1 (left)",
       "opaque, front and back in two colours, adaptive s-stripes (pathlines) that darken only, silhouettes",
       "builtin:toroid", "iris", {"opacity=constant", "alpha=1", "stripe_strength=0", "stripe_darken=0.5"}},
      {"iris-fig1-transparent-stripes", paper, "Fig. 1 (right)",
       "transparent (normal variation) with denser stripes, hatching-like, softer silhouettes", "builtin:toroid", "iris",
       {"stripe_period=8", "silhouette_threshold=2", "silhouette_softness=2"}},
      {"iris-fig10a-normal-variation", paper, "Fig. 10 (a)", "normal-variation transparency, two-sided colour, silhouettes",
       "builtin:bubble", "iris", {"stripes=off"}},
      {"iris-fig10b-grid", paper, "Fig. 10 (b)", "adaptive grid (streamlines and timelines), multiplicative opacity",
       "builtin:bubble", "iris", {"stripes=both"}},
      {"iris-fig10c-lic", paper, "Fig. 10 (c)", "noise blurred along t (LIC-like), cool-warm shading, silhouettes",
       "builtin:bubble", "iris", {"stripes=lic", "shading=gooch", "opacity=constant", "alpha=0.9"}},
      {"iris-fig10a-peeled", paper, "Fig. 10 (a), Sec. 5.1", "the same as Fig. 10 (a) by depth peeling",
       "builtin:bubble", "iris", {"stripes=off"}, "", "peel"},
  };
}

std::vector<FigureSpec> diepstraten() {
  const std::string paper = "Diepstraten et al. 2002 (seed 001)";
  return {
      {"diepstraten-fig3a-standard", paper, "Fig. 3 (a)", "standard view-independent blending of the box in the mug",
       "builtin:mug-box", "constant", {"alpha=0.5"}},
      {"diepstraten-fig3b-mug-box", paper, "Fig. 3 (b) / Fig. 9",
       "view-dependent transparency (Eq. 2, k = 0.5), Gooch shading, black silhouettes, explicit boundaries",
       "builtin:mug-box", "view-dependent", {}},
      {"diepstraten-fig9-crank", paper, "Fig. 9",
       "the crank inside the cylinder, implicit interior boundaries (Sec. 6.1)", "builtin:crank-cylinder",
       "view-dependent", {"boundaries=implicit"}},
      {"diepstraten-fig9-mugs", paper, "Fig. 9", "nested mugs: opaque behind two transparent layers is hidden (rule 2)",
       "builtin:mugs", "view-dependent", {}},
  };
}

std::vector<FigureSpec> murray() {
  const std::string paper = "Murray et al. 2016 (seed 002)";
  const std::string scene = "builtin:crank-cylinder";
  return {
      {"murray-fig9a-oit", paper, "Fig. 9 (a)", "k-buffer OIT, constant opacity 0.6", scene, "curvature", {"mode=plain"}},
      {"murray-fig6a-shading", paper, "Fig. 6 (a) / Fig. 9 (b)",
       "mean-curvature shading (bright convex, dark concave) of physically based shading", scene, "curvature",
       {"mode=shading", "shading_tf=fig6a"}},
      {"murray-fig6b-shading", paper, "Fig. 6 (b)", "the alternative shading transfer function", scene, "curvature",
       {"mode=shading", "shading_tf=fig6b"}},
      {"murray-fig7a-transparency", paper, "Figs. 7 (a), 8 (a), 9 (c)",
       "mean-curvature transparency: opacity from |kappa| and depth", scene, "curvature",
       {"mode=transparency", "opacity_tf=fig7a"}},
      {"murray-fig7b-transparency", paper, "Figs. 7 (b), 8 (b)", "the second opacity transfer function", scene, "curvature",
       {"mode=transparency", "opacity_tf=fig7b"}},
  };
}

std::vector<FigureSpec> elmqvist() {
  const std::string paper = "Elmqvist et al. 2008 (seed 004)";
  return {
      {"elmqvist-abstract-opaque", paper, "Fig. 4 (off)", "ABSTRACT world without dynamic transparency",
       "builtin:abstract", "opaque", {}, "fovy=20"},
      {"elmqvist-abstract-dynamic", paper, "Fig. 4 (on)",
       "red targets through the distractors: outline mask, (1 - alpha_T)^k per occluder", "builtin:abstract", "dynamic", {},
       "fovy=20"},
      {"elmqvist-walkthrough-opaque", paper, "Fig. 7 (off)", "WALKTHROUGH, first person in the centre, walls opaque",
       "builtin:walkthrough", "opaque", {}},
      {"elmqvist-walkthrough-dynamic", paper, "Fig. 7 (on)", "all objects made visible through the walls",
       "builtin:walkthrough", "dynamic", {}},
  };
}

}  // namespace

const std::vector<FigureSpec>& figureCatalog() {
  static const std::vector<FigureSpec> figures = [] {
    std::vector<FigureSpec> all;
    for (auto part : {carnecky(), iris(), diepstraten(), murray(), elmqvist()})
      for (auto& f : part) all.push_back(std::move(f));
    return all;
  }();
  return figures;
}

std::string figureCommand(const FigureSpec& f, const std::string& size, const std::string& output) {
  std::string c = "tlab render " + f.scene + " --style " + f.style;
  for (const auto& s : f.settings) c += " --set " + s;
  if (!f.camera.empty()) c += " --camera \"" + f.camera + "\"";
  if (f.renderer != "buffer") c += " --renderer " + f.renderer;
  return c + " --size " + size + " -o " + output;
}

}  // namespace tlab::app
