// ANOVA. Expected values: R 4.2.2 and car 3.1 (reference/reference_values.R): anova(lm()) for
// PlantGrowth, anova.mlm(test = "Spherical") / mauchly.test / car::Anova(type = 3) for the
// repeated-measures data, car::Anova(type = 2 and 3) and aov(Error()) for the mixed and unbalanced
// designs; the offset case against exact rational arithmetic (reference/offset_reference.py).
#include "analysis/anova.hpp"

#include "analysis/csv_reader.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

using testing::relativelyNear;
using testing::throwsWithMessage;

constexpr double kDigits = 1e-10;

Table dataFile(const char* name) { return readCsvFile(std::string(TLAB_TEST_DATA) + "/analysis/" + name); }

const AnovaEffect& effect(const AnovaResult& r, const std::string& name) {
  for (const auto& e : r.effects)
    if (e.name == name) return e;
  throw std::runtime_error("no effect " + name);
}

TEST(Anova, PlantGrowthOneWay) {
  // R: anova(lm(weight ~ group, PlantGrowth)): F = 4.84608786238014 on (2, 27),
  // p = 0.0159099583256229, SS 3.76634 and 10.49209.
  const AnovaResult r = anova(makeAnovaDesign(dataFile("plant_growth.csv"), "weight", {"group"}, {}, ""));
  ASSERT_EQ(r.effects.size(), 1u);
  const AnovaEffect& g = r.effects[0];
  EXPECT_EQ(g.name, "group");
  EXPECT_FALSE(g.withinSubjects);
  EXPECT_TRUE(relativelyNear(g.F, 4.84608786238014, kDigits));
  EXPECT_EQ(g.df1, 2.0);
  EXPECT_EQ(g.df2, 27.0);
  EXPECT_TRUE(relativelyNear(g.p, 0.0159099583256229, kDigits));
  EXPECT_TRUE(relativelyNear(g.ss, 3.76634, kDigits));
  EXPECT_TRUE(relativelyNear(g.ssError, 10.49209, kDigits));
  // Between-only design: generalized η² = partial η² = SS/(SS + SS_error).
  EXPECT_TRUE(relativelyNear(g.eta2Partial, 3.76634 / (3.76634 + 10.49209), kDigits));
  EXPECT_DOUBLE_EQ(g.eta2Generalized, g.eta2Partial);
  EXPECT_FALSE(g.sphericity.has_value());
}

TEST(Anova, OneWayRepeatedMeasuresWithSphericity) {
  // R: fit <- lm(rm ~ 1) on the 8 × 4 matrix of rm_oneway.csv;
  // anova(fit, X = ~1, test = "Spherical"): F = 35.8754219578847 on (3, 21), p = 1.89828399674403e-08,
  // p_GG = 1.90419395985073e-05, p_HF = 1.98593937333539e-06; stats:::sphericity: ε_GG =
  // 0.548761076845484, ε_HF = 0.695483550667977; mauchly.test: W = 0.1669532780967979,
  // p = 0.0724090642827711 (car::Anova reports the same). aov(y ~ w + Error(s/w)): SS_w =
  // 996.34375, SS_error(s:w) = 194.40625, SS_subjects = 1108.71875, so η²_G = 0.433293016049903.
  const AnovaResult r = anova(makeAnovaDesign(dataFile("rm_oneway.csv"), "score", {}, {"condition"}, "subject"));
  ASSERT_EQ(r.effects.size(), 1u);
  const AnovaEffect& w = r.effects[0];
  EXPECT_TRUE(w.withinSubjects);
  EXPECT_TRUE(relativelyNear(w.F, 35.8754219578847, kDigits));
  EXPECT_EQ(w.df1, 3.0);
  EXPECT_EQ(w.df2, 21.0);
  EXPECT_TRUE(relativelyNear(w.p, 1.89828399674403e-08, kDigits));
  EXPECT_TRUE(relativelyNear(w.ss, 996.34375, kDigits));
  EXPECT_TRUE(relativelyNear(w.ssError, 194.40625, kDigits));
  ASSERT_TRUE(w.sphericity.has_value());
  EXPECT_TRUE(relativelyNear(w.sphericity->epsilonGG, 0.548761076845484, kDigits));
  EXPECT_TRUE(relativelyNear(w.sphericity->epsilonHF, 0.695483550667977, kDigits));
  EXPECT_TRUE(relativelyNear(w.pGG, 1.90419395985073e-05, kDigits));
  EXPECT_TRUE(relativelyNear(w.pHF, 1.98593937333539e-06, kDigits));
  EXPECT_TRUE(relativelyNear(w.sphericity->mauchlyW, 0.1669532780967979, kDigits));
  EXPECT_TRUE(relativelyNear(w.sphericity->mauchlyP, 0.0724090642827711, kDigits));
  EXPECT_TRUE(relativelyNear(w.eta2Generalized, 0.433293016049903, kDigits));
  EXPECT_TRUE(relativelyNear(w.eta2Partial, 996.34375 / (996.34375 + 194.40625), kDigits));
}

TEST(Anova, TwoWithinFactors) {
  // R/car: Anova(lm(wide ~ 1), idesign = ~a*b, type = 3) on two_within.csv (6 subjects, 2 × 3):
  // F a = 9.30769230769229 (1, 5), b = 122.151702786378 (2, 10), a:b = 9.0343347639485 (2, 10);
  // p = 0.0283967251276405, 9.40240857167017e-08, 0.00573972207129761;
  // ε_GG b = 0.625106352382893, a:b = 0.611514113857036; ε_HF b = 0.733545104756549,
  // a:b = 0.706673187956291; p_GG b = 1.79585123973661e-05, a:b = 0.020546077004178;
  // p_HF b = 3.90217446012453e-06, a:b = 0.0149711566599336;
  // Mauchly W b = 0.400272215778931 (p 0.160217846724575), a:b = 0.364714767264086 (p 0.133016861460497).
  const AnovaResult r = anova(makeAnovaDesign(dataFile("two_within.csv"), "y", {}, {"a", "b"}, "s"));
  ASSERT_EQ(r.effects.size(), 3u);
  EXPECT_EQ(r.effects[0].name, "a");
  EXPECT_EQ(r.effects[1].name, "b");
  EXPECT_EQ(r.effects[2].name, "a:b");
  EXPECT_TRUE(relativelyNear(effect(r, "a").F, 9.30769230769229, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "b").F, 122.151702786378, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "a:b").F, 9.0343347639485, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "a").p, 0.0283967251276405, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "b").p, 9.40240857167017e-08, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "a:b").p, 0.00573972207129761, kDigits));
  EXPECT_EQ(effect(r, "b").df2, 10.0);
  EXPECT_FALSE(effect(r, "a").sphericity.has_value());  // 2 levels: sphericity holds trivially
  const auto& b = *effect(r, "b").sphericity;
  const auto& ab = *effect(r, "a:b").sphericity;
  EXPECT_TRUE(relativelyNear(b.epsilonGG, 0.625106352382893, kDigits));
  EXPECT_TRUE(relativelyNear(ab.epsilonGG, 0.611514113857036, kDigits));
  EXPECT_TRUE(relativelyNear(b.epsilonHF, 0.733545104756549, kDigits));
  EXPECT_TRUE(relativelyNear(ab.epsilonHF, 0.706673187956291, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "b").pGG, 1.79585123973661e-05, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "a:b").pGG, 0.020546077004178, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "b").pHF, 3.90217446012453e-06, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r, "a:b").pHF, 0.0149711566599336, kDigits));
  EXPECT_TRUE(relativelyNear(b.mauchlyW, 0.400272215778931, kDigits));
  EXPECT_TRUE(relativelyNear(b.mauchlyP, 0.160217846724575, kDigits));
  EXPECT_TRUE(relativelyNear(ab.mauchlyW, 0.364714767264086, kDigits));
  EXPECT_TRUE(relativelyNear(ab.mauchlyP, 0.133016861460497, kDigits));
}

TEST(Anova, MixedDesignTypeIIAndIII) {
  // R/car on mixed.csv (group ctrl n = 4, trt n = 5; time t1-t3):
  // type II: F grp = 16.7482487336998 (1, 7), time = 78.3713124889596 (2, 14), grp:time =
  // 9.22328210563504; p = 0.00461662390258679, 2.49173912921217e-08, 0.00278429494501016
  // (identical to aov(y ~ g*time + Error(s/time))); type III: time F = 71.6928104575164,
  // p = 4.40697804961207e-08, the others unchanged. ε_GG = 0.740066441951208, ε_HF =
  // 0.891422099865398 (Lecoutre's correction, R's stats:::sphericity with error df 7);
  // type II p_GG time = 1.24254884239094e-06, p_HF time = 1.27123979117863e-07;
  // Mauchly W = 0.648769970756316, p = 0.273068886367915.
  const AnovaDesign design = makeAnovaDesign(dataFile("mixed.csv"), "y", {"g"}, {"time"}, "s");
  const AnovaResult r2 = anova(design, SumOfSquaresType::II);
  ASSERT_EQ(r2.effects.size(), 3u);
  EXPECT_EQ(r2.effects[0].name, "g");
  EXPECT_EQ(r2.effects[1].name, "time");
  EXPECT_EQ(r2.effects[2].name, "g:time");
  EXPECT_TRUE(relativelyNear(effect(r2, "g").F, 16.7482487336998, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "time").F, 78.3713124889596, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "g:time").F, 9.22328210563504, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "g").p, 0.00461662390258679, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "time").p, 2.49173912921217e-08, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "g:time").p, 0.00278429494501016, kDigits));
  EXPECT_EQ(effect(r2, "g").df2, 7.0);
  EXPECT_EQ(effect(r2, "time").df2, 14.0);
  const auto& s = *effect(r2, "time").sphericity;
  EXPECT_TRUE(relativelyNear(s.epsilonGG, 0.740066441951208, kDigits));
  EXPECT_TRUE(relativelyNear(s.epsilonHF, 0.891422099865398, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "time").pGG, 1.24254884239094e-06, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "time").pHF, 1.27123979117863e-07, kDigits));
  EXPECT_TRUE(relativelyNear(s.mauchlyW, 0.648769970756316, kDigits));
  EXPECT_TRUE(relativelyNear(s.mauchlyP, 0.273068886367915, kDigits));
  const AnovaResult r3 = anova(design, SumOfSquaresType::III);
  EXPECT_TRUE(relativelyNear(effect(r3, "time").F, 71.6928104575164, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "time").p, 4.40697804961207e-08, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "g").F, 16.7482487336998, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "g:time").F, 9.22328210563504, kDigits));
}

TEST(Anova, UnbalancedBetweenTypeIIAndIII) {
  // R/car: Anova(lm(y ~ a*b, ub), type = 2): F a = 0.450089303433223, b = 63.9691926780635,
  // a:b = 5.66163921412979 on (·, 10); type = 3: a = 0.698072277613924, b = 51.4094916791881,
  // a:b unchanged; p (type III) a = 0.422945352515071, b = 5.47128188636566e-06.
  const AnovaDesign design = makeAnovaDesign(dataFile("unbalanced_between.csv"), "y", {"a", "b"}, {}, "");
  const AnovaResult r2 = anova(design, SumOfSquaresType::II);
  EXPECT_TRUE(relativelyNear(effect(r2, "a").F, 0.450089303433223, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "b").F, 63.9691926780635, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "a:b").F, 5.66163921412979, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r2, "a").p, 0.51748758121487, kDigits));
  EXPECT_EQ(effect(r2, "a:b").df2, 10.0);
  const AnovaResult r3 = anova(design, SumOfSquaresType::III);
  EXPECT_TRUE(relativelyNear(effect(r3, "a").F, 0.698072277613924, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "b").F, 51.4094916791881, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "a:b").F, 5.66163921412979, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "a").p, 0.422945352515071, kDigits));
  EXPECT_TRUE(relativelyNear(effect(r3, "b").p, 5.47128188636566e-06, kDigits));
}

TEST(Anova, BalancedDesignsGiveTheSameTypeIIAndIII) {
  const AnovaDesign design = makeAnovaDesign(dataFile("two_within.csv"), "y", {}, {"a", "b"}, "s");
  const AnovaResult r2 = anova(design, SumOfSquaresType::II);
  const AnovaResult r3 = anova(design, SumOfSquaresType::III);
  for (std::size_t i = 0; i < r2.effects.size(); ++i) EXPECT_TRUE(relativelyNear(r2.effects[i].F, r3.effects[i].F, 1e-12));
}

TEST(Anova, OffsetByOneBillion) {
  // Two groups 1e9 + 0.001·{1,2,4,7,11} and 1e9 + 0.001·{3,5,6,9,10,12}: exact one-way F =
  // 1.2421827105076544109241 (offset_reference.py; = Student t²).
  char buffer[64];
  std::string csv = "g,y\n";
  for (const int k : {1, 2, 4, 7, 11}) {
    std::snprintf(buffer, sizeof buffer, "a,%.17g\n", 1e9 + 0.001 * k);
    csv += buffer;
  }
  for (const int k : {3, 5, 6, 9, 10, 12}) {
    std::snprintf(buffer, sizeof buffer, "b,%.17g\n", 1e9 + 0.001 * k);
    csv += buffer;
  }
  const AnovaResult r = anova(makeAnovaDesign(parseCsv(csv, "offset.csv"), "y", {"g"}, {}, ""));
  EXPECT_TRUE(relativelyNear(r.effects[0].F, 1.2421827105076544109241, 1e-9));
}

TEST(Anova, ReplicatesAreAveragedPerSubjectAndCell) {
  // Two trials per subject and cell, each pair averaging to the rm_oneway.csv values, must give
  // the same F as the averaged data (R value above: 35.8754219578847).
  const Table base = dataFile("rm_oneway.csv");
  std::string csv = "subject,condition,score\n";
  for (std::size_t r = 0; r < base.rowCount(); ++r) {
    const double v = base.number(r, 2);
    csv += base.text(r, 0) + "," + base.text(r, 1) + "," + std::to_string(v - 1.5) + "\n";
    csv += base.text(r, 0) + "," + base.text(r, 1) + "," + std::to_string(v + 1.5) + "\n";
  }
  const AnovaResult r = anova(makeAnovaDesign(parseCsv(csv, "trials.csv"), "score", {}, {"condition"}, "subject"));
  EXPECT_EQ(r.maxReplicates, 2u);
  EXPECT_TRUE(relativelyNear(r.effects[0].F, 35.8754219578847, kDigits));
}

TEST(Anova, ImpossibleDesignsHaveClearErrors) {
  const Table rm = dataFile("rm_oneway.csv");
  // Unbalanced within-subject data: drop subject s3's c2 row.
  std::string csv = "subject,condition,score\n";
  for (std::size_t r = 0; r < rm.rowCount(); ++r)
    if (!(rm.text(r, 0) == "s3" && rm.text(r, 1) == "c2"))
      csv += rm.text(r, 0) + "," + rm.text(r, 1) + "," + rm.text(r, 2) + "\n";
  EXPECT_TRUE(throwsWithMessage(
      [&] { makeAnovaDesign(parseCsv(csv, "u.csv"), "score", {}, {"condition"}, "subject"); },
      {"unbalanced within-subject data", "subject 's3'", "cell condition=c2"}));
  // One-level factor.
  EXPECT_TRUE(throwsWithMessage([] { makeAnovaDesign(parseCsv("g,y\na,1\na,2\na,3\n", "one.csv"), "y", {"g"}, {}, ""); },
                                {"factor 'g' has only one level ('a')"}));
  // Non-numeric dv with file:line.
  EXPECT_TRUE(throwsWithMessage([] { makeAnovaDesign(parseCsv("g,y\na,1\nb,x\n", "bad.csv"), "y", {"g"}, {}, ""); },
                                {"bad.csv:3", "'x' is not a number"}));
  // A subject in two between groups.
  EXPECT_TRUE(throwsWithMessage(
      [] { makeAnovaDesign(parseCsv("s,g,w,y\n1,a,p,1\n1,b,q,2\n2,a,p,3\n2,a,q,4\n", "sw.csv"), "y", {"g"}, {"w"}, "s"); },
      {"subject '1'", "must be constant within a subject"}));
  // Zero error variance: every subject's condition effect identical.
  EXPECT_TRUE(throwsWithMessage(
      [] { anova(makeAnovaDesign(parseCsv("s,w,y\n1,p,1\n1,q,3\n2,p,5\n2,q,7\n3,p,2\n3,q,4\n", "z.csv"), "y", {}, {"w"}, "s")); },
      {"zero error variance", "effect 'w'", "F would be infinite"}));
  // Within factors without a subject column.
  EXPECT_TRUE(throwsWithMessage([&] { makeAnovaDesign(rm, "score", {}, {"condition"}, ""); }, {"need a subject column"}));
}

}  // namespace
}  // namespace tlab::analysis
