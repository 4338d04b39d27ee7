#include "stimuli/scenes/stimulus_scenes.hpp"

#include "stimuli/scenes/abstract_world.hpp"
#include "stimuli/scenes/flow_surface_scenes.hpp"
#include "stimuli/scenes/walkthrough_scene.hpp"

namespace tlab::stimuli {

namespace {

using Params = std::map<std::string, double>;

std::uint64_t asSeed(const Params& p) { return std::uint64_t(p.at("seed")); }

render::SceneParam seedParam() { return {"seed", 1, 0, 1e9, true, "random seed: the same seed gives the same scene"}; }

std::vector<render::SceneParam> flowSurfaceParams() {
  return {seedParam(), {"resolution", 1, 0.25, 4, false, "particle density of the advancing front"},
          {"time", 1, 0.1, 3, false, "scales the integration time"}};
}

FlowSurfaceParams toFlowSurfaceParams(const Params& p) { return {asSeed(p), p.at("resolution"), p.at("time")}; }

render::Scene buildAbstract(const Params& p) {
  AbstractWorldParams a;
  a.seed = asSeed(p);
  return abstractWorldScene(a);
}

render::Scene buildWalkthrough(const Params& p) {
  WalkthroughParams w;
  w.seed = asSeed(p);
  w.objects = int(p.at("objects"));
  return walkthroughScene(w);
}

}  // namespace

const std::vector<render::BuiltinSceneSpec>& stimulusScenes() {
  static const std::vector<render::BuiltinSceneSpec> specs = {
      {"pretzel", "stream surface winding around Hill's spherical vortex with swirl (Carnecky's pretzel)", flowSurfaceParams(),
       [](const Params& p) { return pretzelScene(toFlowSurfaceParams(p)); }},
      {"bubble", "stream surface of a swirling jet wrapping its vortex-breakdown bubble (Carnecky's bubble)", flowSurfaceParams(),
       [](const Params& p) { return bubbleScene(toFlowSurfaceParams(p)); }},
      {"toroid", "stream surface rolling up around a vortex ring's core (Carnecky's toroid)", flowSurfaceParams(),
       [](const Params& p) { return toroidScene(toFlowSurfaceParams(p)); }},
      {"abstract", "Elmqvist's ABSTRACT world: 200 spheres/cones/boxes/tori in a 100^3 cube, 10-20 % red targets", {seedParam()},
       buildAbstract},
      {"walkthrough", "Elmqvist's WALKTHROUGH: 16x16 rooms with doorways, 50 objects, one unique trophy, counted chairs",
       {seedParam(), {"objects", 50, 30, 200, true, "number of objects (at least 30: every kind twice, the counted kind up to 10 times)"}}, buildWalkthrough},
  };
  return specs;
}

render::BuiltinSceneSpec abstractPatternSpec(const std::string& letters, LetterCells cells) {
  std::string help = "Elmqvist T2: red cones on a rotated 5x7 letter among red distractors; letter = index into " + letters;
  return {"abstract-pattern", help,
          {seedParam(), {"letter", 0, 0, double(letters.size()) - 1, true, "which letter: 0.." + std::to_string(letters.size() - 1) + " of " + letters},
           {"distractors", 12, 0, 60, true, "red objects of other shapes"}},
          [letters, cells](const Params& p) {
            AbstractPatternParams a;
            a.seed = asSeed(p);
            a.redDistractors = int(p.at("distractors"));
            return abstractPatternScene(a, cells(letters[std::size_t(p.at("letter"))]));
          }};
}

std::vector<render::BuiltinSceneSpec> allSceneSpecs(const std::vector<render::BuiltinSceneSpec>& extra) {
  std::vector<render::BuiltinSceneSpec> all = render::builtinScenes();
  const auto& more = stimulusScenes();
  all.insert(all.end(), more.begin(), more.end());
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

}  // namespace tlab::stimuli
