// HTML text through libxml2's HTML parser (document_text.hpp): the text nodes in document order,
// a line break after every block element, nothing from <script>, <style> or <sub> (statcheck's
// getHTML drops subscripts, which would otherwise split "F<sub>change</sub>(1, 20)"), except a
// subscript starting with "rep" (p<sub>rep</sub>).
#include <libxml/HTMLparser.h>
#include <libxml/tree.h>

#include <cstring>
#include <memory>
#include <string_view>

#include "analysis/analysis_error.hpp"
#include "analysis/document_module.hpp"

namespace tlab::analysis {

namespace {

struct DocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};

bool named(const xmlNode* n, const char* name) {
  return n->name != nullptr && xmlStrcasecmp(n->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}

std::string nodeText(const xmlNode* n) {
  xmlChar* content = xmlNodeGetContent(n);
  std::string s = content != nullptr ? reinterpret_cast<const char*>(content) : "";
  xmlFree(content);
  return s;
}

bool isBlock(const xmlNode* n) {
  static constexpr const char* blocks[] = {"p", "div", "br", "li", "tr", "td", "th", "h1", "h2", "h3", "h4",
                                           "h5", "h6", "table", "section", "article", "blockquote", "pre"};
  for (const char* b : blocks)
    if (named(n, b)) return true;
  return false;
}

// Iterative walk: a hostile, deeply nested document cannot exhaust the stack.
void appendText(const xmlNode* root, std::string& out) {
  const xmlNode* n = root;
  while (n != nullptr) {
    bool descend = false;
    if (n->type == XML_TEXT_NODE || n->type == XML_CDATA_SECTION_NODE) {
      out += nodeText(n);
    } else if (n->type == XML_ELEMENT_NODE) {
      if (named(n, "script") || named(n, "style")) {
      } else if (named(n, "sub")) {
        const std::string sub = nodeText(n);
        if (sub.rfind("rep", 0) == 0) out += sub;
      } else {
        descend = n->children != nullptr;
      }
    }
    if (descend) {
      n = n->children;
      continue;
    }
    while (n != nullptr && n != root && n->next == nullptr) {
      n = n->parent;
      if (n != nullptr && n->type == XML_ELEMENT_NODE && isBlock(n)) out += "\n";
    }
    if (n == nullptr || n == root) break;
    if (n->type == XML_ELEMENT_NODE && isBlock(n)) out += "\n";
    n = n->next;
  }
}

}  // namespace

std::string htmlTextWithLibxml2(std::string_view html, const std::string& source) {
  const int options = HTML_PARSE_RECOVER | HTML_PARSE_NOERROR | HTML_PARSE_NOWARNING | HTML_PARSE_NONET;
  const std::unique_ptr<xmlDoc, DocFree> doc(
      htmlReadMemory(html.data(), static_cast<int>(html.size()), source.c_str(), nullptr, options));
  if (!doc) {
    if (html.empty()) return {};
    throw AnalysisError(source + ": not readable as HTML");
  }
  std::string out;
  const xmlNode* root = xmlDocGetRootElement(doc.get());
  if (root != nullptr) appendText(root, out);
  return out;
}

}  // namespace tlab::analysis
