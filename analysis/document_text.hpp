#pragma once
// The text of a manuscript for statcheck: plain text as is, PDF through poppler (reading order,
// then statcheck's typesetting fixes), HTML through libxml2's HTML parser (text nodes only;
// script, style and <sub> content dropped as statcheck's getHTML does, except a "rep" subscript).
// Folders are searched recursively for .txt, .pdf, .htm and .html files.
#include <string>
#include <string_view>
#include <vector>

namespace tlab::analysis {

enum class DocumentFormat { Text, Pdf, Html };

// By extension (case-insensitive): .pdf, .htm/.html/.xhtml; anything else is text.
DocumentFormat documentFormatOf(const std::string& path);
// Throws AnalysisError naming the file when it cannot be opened or parsed.
std::string readDocumentText(const std::string& path);
std::string pdfText(const std::string& path);
std::string htmlText(std::string_view html, const std::string& source);

// statcheck's corrections of PDF extraction (R/file-to-txt.R getPDF): ⫽ and ¼ → "=", U+2B0D and
// "!" → "<", U+2AFA → "-", U+2439 → χ; a "b" / "N" not after = < > and followed by a number
// (optionally " -" or ".") → "<" / ">"; a "p" followed by a number and not after ", " → "=";
// "B" before t, F, r, Q, z, Z → a quote.
std::string fixPdfTypesetting(std::string_view text);

// Files given and, for folders, every .txt/.pdf/.htm/.html below them, each folder's in sorted
// order. Throws AnalysisError for a path that does not exist or a folder without documents.
std::vector<std::string> collectDocuments(const std::vector<std::string>& paths);

}  // namespace tlab::analysis
