// Smart transparency's solve (Carnecky Sec. 5.4): α diffusion under both readings of Eq. 8 (the
// normalised Laplacian and the sum), its stability for every λα and scheme, and β/γ spreading by
// Eq. 9 — against analytic expectations and against the unabridged computation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/scene/scene_source.hpp"
#include "tests/renderer/smart_rig.hpp"
#include "tests/support/gl_fixture.hpp"

using namespace tlab::render;
using namespace tlab::testing;

// Eq. 9 spreads β from the boundary so that 1 − β = λβ·d at graph distance d (until it reaches 0).
// The front quad's only boundary is its edge at column 31: the image edges (rows 0 and 15, column
// 0) cut the surface and start nothing (issue #20: they used to be drawn as silhouettes).
TEST(FieldSpreading, MaxPropagationIsLinearInDistance) {
  const int w = 64, h = 16, n = 12;
  SmartRig rig(occluderScene(), w, h, {{"iterations", std::to_string(n)}, {"lambda_beta", "0.05"}, {"halos", "off"}});
  DiffusionSolver(rig.shaders, rig.smart).solve(*rig.fields);
  const auto beta = rig.fields->read(Field::Beta);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < 32; ++x) {
      const int d = 31 - x;
      const float expected = d <= n ? 1.0f - 0.05f * d : 0.0f;
      ASSERT_NEAR(beta[rig.fragment(x, y, 0)], expected, 1e-5) << x << "," << y;
    }
}

// Stability of α diffusion for any λα and iteration count: fields stay in [0, 1], no NaN, and the
// discrete energy Σ (α_i − α_j)² over the links never increases.
class DiffusionStability : public ::testing::TestWithParam<std::tuple<double, std::string, std::string>> {};
TEST_P(DiffusionStability, FieldsStayBoundedAndEnergyDecays) {
  const auto [lambda, solver, laplacian] = GetParam();
  SmartRig rig(loadScene("builtin:open-cylinders?segments=48&rings=4"), 40, 40,
               {{"lambda_alpha", std::to_string(lambda)}, {"solver", solver}, {"alpha_init", "adaptive"}, {"s", "0.7"},
                {"laplacian", laplacian}});
  const DiffusionSolver solver_(rig.shaders, rig.smart);
  // Forced sub-stepping at λα = 1000 costs 1000-4000 passes per step (solver=auto goes implicit
  // there): 20 steps of it are enough to check it.
  const int steps = solver == "substep" && lambda > 10 ? 20 : 1000;
  const auto links = rig.fields->readLinks();
  double energy = linkEnergy(rig.fields->read(Field::Alpha), links);
  ASSERT_GT(energy, 0.0);
  for (int step = 1; step <= steps; ++step) {
    solver_.step(*rig.fields);
    if (step <= 20 || step == steps) {
      const auto alpha = rig.fields->read(Field::Alpha);
      for (float a : alpha) ASSERT_TRUE(a >= 0.0f && a <= 1.0f) << "step " << step << " alpha " << a;
      const double e = linkEnergy(alpha, links);
      ASSERT_LE(e, energy * (1 + 1e-5) + 1e-9) << "energy grew at step " << step;
      energy = e;
      for (float b : rig.fields->read(Field::Beta)) ASSERT_TRUE(b >= 0.0f && b <= 1.0f);
      for (float g : rig.fields->read(Field::Gamma)) ASSERT_TRUE(g >= 0.0f && g <= 1.0f);
    }
  }
}
// Every scheme at every λα for both readings of Eq. 8, except explicit above its bound (refused:
// see the next test).
std::vector<std::tuple<double, std::string, std::string>> stabilityCases() {
  std::vector<std::tuple<double, std::string, std::string>> cases;
  for (const char* laplacian : {"normalized", "sum"}) {
    const double bound = std::string(laplacian) == "sum" ? kExplicitStableLambdaSum : kExplicitStableLambdaNormalized;
    for (double lambda : {0.0, 0.25, 1.0, 10.0, 1000.0})
      for (const char* solver : {"auto", "explicit", "substep", "implicit"})
        if (std::string(solver) != "explicit" || lambda <= bound) cases.emplace_back(lambda, solver, laplacian);
  }
  return cases;
}
INSTANTIATE_TEST_SUITE_P(LambdaAndScheme, DiffusionStability, ::testing::ValuesIn(stabilityCases()),
                         [](const auto& info) {
                           const double l = std::get<0>(info.param);
                           return "lambda_" + (l == 0.25 ? std::string("quarter") : std::to_string(int(l))) + "_" +
                                  std::get<1>(info.param) + "_" + std::get<2>(info.param);
                         });

TEST(DiffusionStability, ExplicitAboveTheBoundIsRefusedWithTheReason) {
  for (const auto& [laplacian, lambda] : {std::pair{"normalized", "1.5"}, std::pair{"sum", "1"}}) {
    try {
      SmartStyle().resolve({{"solver", "explicit"}, {"lambda_alpha", lambda}, {"laplacian", laplacian}});
      FAIL() << laplacian;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("unstable"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(SmartStyle().resolve({{"solver", "explicit"}, {"lambda_alpha", "1"}}));
  // The paper's λα = 1 is one explicit pass per step with the normalised reading, 4 with the sum.
  EXPECT_EQ(automaticScheme(1.0, kExplicitStableLambdaNormalized), DiffusionScheme::Explicit);
  EXPECT_EQ(automaticScheme(0.25, kExplicitStableLambdaSum), DiffusionScheme::Explicit);
  EXPECT_EQ(automaticScheme(1.0, kExplicitStableLambdaSum), DiffusionScheme::Substep);
  EXPECT_EQ(automaticScheme(1000.0, kExplicitStableLambdaNormalized), DiffusionScheme::Implicit);
  EXPECT_EQ(substepsFor(1.0, kExplicitStableLambdaSum), 4);
  EXPECT_EQ(substepsFor(1.0, kExplicitStableLambdaNormalized), 1);
  EXPECT_EQ(substepsFor(3.0, kExplicitStableLambdaNormalized), 3);
}

// The normalised reading of Eq. 8 at λα = 1 is α' = mean of the neighbours (for free fragments):
// one explicit step checked on the host from the links.
TEST(DiffusionStability, NormalizedStepIsTheMeanOfTheNeighbours) {
  SmartRig rig(loadScene("builtin:open-cylinders?segments=48&rings=4"), 40, 40,
               {{"alpha_init", "adaptive"}, {"s", "0.7"}, {"iterations", "1"}});
  const auto before = rig.fields->read(Field::Alpha);
  const auto links = rig.fields->readLinks();
  DiffusionSolver(rig.shaders, rig.smart).step(*rig.fields);
  const auto after = rig.fields->read(Field::Alpha);
  for (std::size_t i = 0; i < links.size(); ++i) {
    double sum = 0;
    int degree = 0;
    for (int k = 0; k < 4; ++k)
      if (links[i][k] != kNone) sum += before[links[i][k]], ++degree;
    const double expected = degree > 0 ? sum / degree : before[i];
    ASSERT_NEAR(after[i], expected, 1e-6) << "fragment " << i;
  }
}

// Eq. 9 settles after ⌈1/λ⌉ steps: the solve that stops spreading there gives exactly the fields of
// n full steps.
TEST(FieldSpreading, SettledSpreadingStopsWithoutChangingTheFields) {
  for (const char* alphaInit : {"constant", "adaptive"}) {
    const std::map<std::string, std::string> settings = {{"iterations", "30"}, {"lambda_beta", "0.05"}, {"lambda_gamma", "0.2"},
                                                         {"alpha_init", alphaInit}};
    SmartRig solved(occluderScene(), 64, 16, settings), stepped(occluderScene(), 64, 16, settings);
    const DiffusionSolver solver(solved.shaders, solved.smart);
    solver.solve(*solved.fields);
    const DiffusionSolver full(stepped.shaders, stepped.smart);
    for (int i = 0; i < 30; ++i) full.step(*stepped.fields);
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma})
      EXPECT_EQ(solved.fields->read(f), stepped.fields->read(f)) << alphaInit << " field " << int(f);
    const auto gamma = solved.fields->read(Field::Gamma);
    EXPECT_GT(*std::max_element(gamma.begin(), gamma.end()), 0.5f);  // there is a halo to spread
  }
  // A full-frame stack has no silhouette and no occluding edge: one step shows nothing moves.
  SmartRig stack(loadScene("builtin:quad-stack?n=4"), 24, 24, {{"iterations", "20"}});
  const DiffusionSolver solver(stack.shaders, stack.smart);
  solver.solve(*stack.fields);
  EXPECT_EQ(solver.operations()[1], "beta spreading (Eq. 9 max, 1 of 20 steps: settled)");
  EXPECT_EQ(solver.operations()[2], "gamma spreading (Eq. 9 max, 1 of 20 steps: settled)");
}


// The connect pass lists Eq. 9's seeds — exactly the fragments where β and γ start above 0 — and
// the solve spreads from them on the frontier only (ops/spread_frontier.comp): bit for bit the
// fields of n full steps of every fragment, on scenes with silhouettes, halos, several
// components, deep and shuffled stacks, lists longer than 32 layers, for both initial α (adaptive α diffuses alongside), for λ
// that settles within n steps and λ that does not, and with halos off; the steps run as host code
// and as the shader, reading the fields through buffer textures and through storage buffers alike.
TEST(FieldSpreading, FrontierSpreadingEqualsFullSteps) {
  struct Case {
    const char* source;
    int size;
    std::map<std::string, std::string> settings;
    bool seeded = true;  // the scene has silhouettes or occluding edges to spread from
    std::uint32_t deepSeed = 0;  // some seed lies at least this deep in its list
  };
  const std::vector<Case> cases = {
      {"builtin:torus", 64, {}},
      {"builtin:torus", 48, {{"alpha_init", "adaptive"}, {"iterations", "7"}}},
      {"builtin:nested-spheres?n=3", 64, {{"lambda_beta", "0.02"}, {"lambda_gamma", "0.3"}}},
      {"builtin:open-cylinders", 64, {{"iterations", "50"}, {"lambda_beta", "0.01"}}},
      {"builtin:open-cylinders", 40, {{"halos", "off"}, {"lambda_beta", "0"}, {"iterations", "9"}}},
      {"builtin:nested-spheres?n=2", 48, {{"lambda_gamma", "1"}}},
      {"builtin:nested-spheres?n=20", 64, {}, true, 32},  // seeds listed 32 layers at a time
      {"builtin:quad-stack?n=64", 24, {}, false},
      {"builtin:quad-stack?n=16", 32, {}, false},
      {"builtin:sphere?segments=8&rings=4", 24, {{"alpha_init", "adaptive"}, {"solver", "implicit"}}},
  };
  for (const auto& c : cases) {
    const std::string what = std::string(c.source) + " " + std::to_string(c.settings.size()) + " settings";
    SmartRig frontier(loadScene(c.source), c.size, c.size, c.settings), full(loadScene(c.source), c.size, c.size, c.settings);
    ASSERT_TRUE(frontier.fields->seedsListed()) << what;
    std::size_t seeds = 0;
    std::vector<std::uint32_t> layerOf(frontier.buffer->fragmentCount());
    for (std::size_t p = 0; p < frontier.counts.size(); ++p)
      for (std::uint32_t k = 0; k < frontier.counts[p]; ++k) layerOf[frontier.heads[p] + k] = k;
    std::uint32_t deepest = 0;
    for (Field f : {Field::Beta, Field::Gamma}) {
      if (f == Field::Gamma && !frontier.fields->hasGamma()) continue;
      const auto values = frontier.fields->read(f);
      std::vector<std::uint32_t> expected;
      for (std::uint32_t i = 0; i < values.size(); ++i)
        if (values[i] > 0.0f) expected.push_back(i);
      auto listed = frontier.fields->readList(f);
      std::sort(listed.begin(), listed.end());
      EXPECT_EQ(listed, expected) << what << " field " << int(f);
      seeds += listed.size();
      for (auto i : listed) deepest = std::max(deepest, layerOf[i]);
    }
    EXPECT_EQ(seeds > 0u, c.seeded) << what;
    EXPECT_GE(deepest, c.deepSeed) << what;
    // The steps as host code (the default where the GL runs on the CPU, as on llvmpipe), as the shader
    // reading buffer textures, and as the shader reading storage buffers (where texels run out).
    DiffusionSolver shader(frontier.shaders, frontier.smart), buffers(frontier.shaders, frontier.smart);
    shader.setFrontierOnHost(false);
    buffers.setFrontierOnHost(false);
    buffers.setFieldTexels(false);
    SmartRig throughShader(loadScene(c.source), c.size, c.size, c.settings),
        throughBuffers(loadScene(c.source), c.size, c.size, c.settings);
    shader.solve(*throughShader.fields);
    buffers.solve(*throughBuffers.fields);
    DiffusionSolver solver(frontier.shaders, frontier.smart);
    EXPECT_EQ(solver.frontierOnHost(), tlab::gpu::hostPassesWanted());  // the default: on where the GL is the CPU
    solver.setFrontierOnHost(true);
    solver.solve(*frontier.fields);
    EXPECT_FALSE(frontier.fields->seedsListed()) << what;
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) {
      if (f == Field::Gamma && !frontier.fields->hasGamma()) continue;
      EXPECT_EQ(throughShader.fields->read(f), frontier.fields->read(f)) << what << " field " << int(f) << ", shader";
      EXPECT_EQ(throughBuffers.fields->read(f), frontier.fields->read(f)) << what << " field " << int(f) << ", storage buffers";
    }
    EXPECT_EQ(shader.operations(), solver.operations()) << what;
    EXPECT_EQ(buffers.operations(), solver.operations()) << what;
    const DiffusionSolver stepper(full.shaders, full.smart);
    for (int i = 0; i < full.smart.iterations; ++i) stepper.step(*full.fields);
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) {
      if (f == Field::Gamma && !full.fields->hasGamma()) continue;
      EXPECT_EQ(frontier.fields->read(f), full.fields->read(f)) << what << " field " << int(f);
    }
    // The same steps as the full solve, which checks for a settled field after steps 1, 2, 4, 8, ...
    SmartRig again(loadScene(c.source), c.size, c.size, c.settings);
    again.fields->setSeedsListed(false);
    const DiffusionSolver reference(again.shaders, again.smart);
    reference.solve(*again.fields);
    EXPECT_EQ(solver.operations(), reference.operations()) << what;
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) {
      if (f == Field::Gamma && !again.fields->hasGamma()) continue;
      EXPECT_EQ(frontier.fields->read(f), again.fields->read(f)) << what << " field " << int(f);
    }
  }
}
