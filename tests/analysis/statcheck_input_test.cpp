// statcheck's inputs: PDF through poppler with statcheck's typesetting fixes, HTML through
// libxml2, folders searched recursively. The PDF fixture is written by
// tests/data/analysis/statcheck_sample_pdf.py (two pages, the second in two columns; Helvetica);
// expected results are read off the fixture texts.
#include <filesystem>
#include <fstream>

#include "analysis/document_text.hpp"
#include "analysis/statcheck.hpp"
#include "tests/analysis/test_support.hpp"

namespace tlab::analysis {
namespace {

namespace fs = std::filesystem;

std::string data(const char* name) { return std::string(TLAB_TEST_DATA) + "/analysis/" + name; }

TEST(StatcheckInput, FormatFollowsTheExtension) {
  EXPECT_EQ(documentFormatOf("a/paper.PDF"), DocumentFormat::Pdf);
  EXPECT_EQ(documentFormatOf("paper.htm"), DocumentFormat::Html);
  EXPECT_EQ(documentFormatOf("paper.html"), DocumentFormat::Html);
  EXPECT_EQ(documentFormatOf("paper.txt"), DocumentFormat::Text);
  EXPECT_EQ(documentFormatOf("README"), DocumentFormat::Text);
}

// statcheck's getPDF fixes (R/file-to-txt.R, R/regex.R RGX_B_SMALLER, RGX_N_LARGER, RGX_P_EQUAL,
// RGX_B_QUOTE and the code-point substitutions).
TEST(StatcheckInput, PdfTypesettingFixes) {
  EXPECT_EQ(fixPdfTypesetting("p b .001"), "p < .001");             // JESP: b for <
  EXPECT_EQ(fixPdfTypesetting("p N .05"), "p > .05");               // JESP: N for >
  EXPECT_EQ(fixPdfTypesetting("t(28) p 2.20, p p .03"), "t(28) = 2.20, p = .03");  // JCR: p for =
  EXPECT_EQ(fixPdfTypesetting("Bt(28)"), "\"t(28)");                // BRM: B for a quote
  EXPECT_EQ(fixPdfTypesetting("p \xE2\xAB\xBD .03, p \xC2\xBC .03, p \xE2\xAC\x8D .03, p ! .03"),
            "p = .03, p = .03, p < .03, p < .03");
  EXPECT_EQ(fixPdfTypesetting("t(28) = \xE2\xAB\xBA" "2.2, \xE2\x90\xB9" "2(1)"), "t(28) = -2.2, \xCF\x87" "2(1)");
  EXPECT_EQ(fixPdfTypesetting("p =b2, p <N3"), "p =b2, p <N3");  // right after a comparison sign: kept
  // Deliberate difference: a letter inside a word is left alone (statcheck: "lab 1" → "la< 1").
  EXPECT_EQ(fixPdfTypesetting("lab 1, Web 2.0, step 3"), "lab 1, Web 2.0, step 3");
}

TEST(StatcheckInput, PdfThroughPoppler) {
  const std::string text = readDocumentText(data("statcheck_sample.pdf"));
  EXPECT_NE(text.find("t(28) = 2.20, p = .04"), std::string::npos) << text;
  EXPECT_NE(text.find("p < .001"), std::string::npos) << text;  // "p b .001" fixed
  const StatcheckReport r = statcheckFile(data("statcheck_sample.pdf"));
  ASSERT_EQ(r.verdicts.size(), 4u);
  EXPECT_TRUE(r.verdicts[0].consistent);   // t(28) = 2.20: p = .036 (R), reported .04
  EXPECT_EQ(r.verdicts[1].result.kind, StatisticKind::F);
  EXPECT_TRUE(r.verdicts[1].consistent);
  EXPECT_TRUE(r.verdicts[2].decisionError);  // t(28) = 1.20 gives p = .24
  EXPECT_EQ(r.verdicts[2].result.line, 4u);
  // Page 2 has two columns; in reading order the left column's "t(40) =" / "3.10, p = .004" stay
  // together (physical layout would put the right column's words between them).
  // R: 2*pt(-3.1, 40) = 0.003537, range over [3.095, 3.105] = [0.003489, 0.003585] meets [.0035, .0045].
  EXPECT_EQ(r.verdicts[3].result.text, "t(40) = 3.10, p = .004");
  EXPECT_TRUE(r.verdicts[3].consistent);
}

TEST(StatcheckInput, BrokenPdfIsAOneLineError) {
  const fs::path bad = fs::temp_directory_path() / "tlab_statcheck_broken.pdf";
  std::ofstream(bad) << "%PDF-1.4 this is not a PDF";
  EXPECT_TRUE(testing::throwsWithMessage([&] { readDocumentText(bad.string()); }, {"tlab_statcheck_broken.pdf", "PDF"}));
  fs::remove(bad);
}

// Text nodes only: script and style dropped, <sub> dropped except p_rep, entities decoded.
TEST(StatcheckInput, HtmlThroughLibxml2) {
  const StatcheckReport r = statcheckFile(data("statcheck_sample.html"));
  ASSERT_EQ(r.verdicts.size(), 4u);
  EXPECT_EQ(r.verdicts[0].result.text, "t(28) = 2.20, p < .05");
  EXPECT_EQ(r.verdicts[1].result.text, "F(1, 76) = 23.95, p < .001");
  EXPECT_EQ(r.verdicts[2].result.kind, StatisticKind::ChiSquared);
  EXPECT_EQ(r.verdicts[2].result.statistic.value, 16.78);
  EXPECT_EQ(r.verdicts[3].result.kind, StatisticKind::R);
  EXPECT_EQ(r.verdicts[3].result.statistic.value, -0.22);
  EXPECT_FALSE(r.verdicts[3].consistent);
  EXPECT_EQ(r.pValues.size(), 4u);  // "p_rep = .95" is no p-value
  EXPECT_EQ(htmlText("", "empty.html"), "");
  EXPECT_NE(htmlText("<p>t(28) = 2.20, <b>p = .04", "unclosed.html").find("t(28) = 2.20, p = .04"), std::string::npos);
}

TEST(StatcheckInput, FoldersAreSearchedRecursivelyInSortedOrder) {
  const fs::path dir = fs::temp_directory_path() / "tlab_statcheck_dir_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "b" / "deeper");
  std::ofstream(dir / "b" / "deeper" / "z.txt") << "t(28) = 2.20, p = .04";
  std::ofstream(dir / "a.html") << "<p>t(28) = 2.20, p = .04</p>";
  std::ofstream(dir / "notes.md") << "t(28) = 2.20, p = .04";  // not a document type
  fs::copy_file(data("statcheck_sample.pdf"), dir / "b" / "paper.pdf");
  const auto files = collectDocuments({dir.string()});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0]).filename(), "a.html");
  EXPECT_EQ(fs::path(files[1]).filename(), "z.txt");  // "b/deeper/z.txt" sorts before "b/paper.pdf"
  EXPECT_EQ(fs::path(files[2]).filename(), "paper.pdf");
  EXPECT_TRUE(testing::throwsWithMessage([&] { collectDocuments({(dir / "missing").string()}); }, {"missing", "no such"}));
  fs::create_directories(dir / "empty");
  EXPECT_TRUE(testing::throwsWithMessage([&] { collectDocuments({(dir / "empty").string()}); }, {"empty", "no .txt"}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tlab::analysis
