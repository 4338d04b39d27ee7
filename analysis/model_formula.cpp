#include "analysis/model_formula.hpp"

#include <algorithm>
#include <cctype>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

[[noreturn]] void fail(std::string_view text, const std::string& what) {
  throw AnalysisError("formula '" + std::string(text) + "': " + what);
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

// Splits at `separator` outside parentheses.
std::vector<std::string> splitTopLevel(std::string_view s, char separator) {
  std::vector<std::string> parts;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '(') ++depth;
    if (s[i] == ')') --depth;
    if (s[i] == separator && depth == 0) {
      parts.push_back(trim(s.substr(start, i - start)));
      start = i + 1;
    }
  }
  parts.push_back(trim(s.substr(start)));
  return parts;
}

bool isName(const std::string& s) {
  if (s.empty()) return false;
  if (s.size() >= 2 && s.front() == '`' && s.back() == '`') return true;
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '.'; }) &&
         !std::isdigit(static_cast<unsigned char>(s.front()));
}

std::string unquote(const std::string& s) { return s.size() >= 2 && s.front() == '`' ? s.substr(1, s.size() - 2) : s; }

// The variables of a product `a:b:c` or `a*b*c`.
std::vector<std::string> factorNames(std::string_view formula, const std::string& product, char op) {
  std::vector<std::string> names;
  for (const auto& part : splitTopLevel(product, op)) {
    if (!isName(part)) fail(formula, "'" + part + "' is not a column name");
    names.push_back(unquote(part));
  }
  return names;
}

void addTerm(std::vector<ModelTerm>& terms, ModelTerm term) {
  const auto same = [&](const ModelTerm& t) {
    return t.size() == term.size() && std::all_of(term.begin(), term.end(), [&](const std::string& v) {
             return std::find(t.begin(), t.end(), v) != t.end();
           });
  };
  if (std::none_of(terms.begin(), terms.end(), same)) terms.push_back(std::move(term));
}

// All non-empty subsets of `names` in R's expansion order of a*b*c: a, b, c, a:b, a:c, b:c, a:b:c.
void addCrossing(std::vector<ModelTerm>& terms, const std::vector<std::string>& names) {
  const std::size_t k = names.size();
  for (std::size_t degree = 1; degree <= k; ++degree) {
    std::vector<bool> pick(k, false);
    std::fill(pick.begin(), pick.begin() + static_cast<std::ptrdiff_t>(degree), true);
    do {
      ModelTerm term;
      for (std::size_t i = 0; i < k; ++i)
        if (pick[i]) term.push_back(names[i]);
      addTerm(terms, term);
    } while (std::prev_permutation(pick.begin(), pick.end()));
  }
}

LinearPredictor parsePredictor(std::string_view formula, std::string_view text) {
  LinearPredictor p;
  std::string s = trim(text);
  // "-1" / "- 1" removes the intercept.
  for (std::size_t at; (at = s.find('-')) != std::string::npos;) {
    std::size_t end = at + 1;
    while (end < s.size() && std::isspace(static_cast<unsigned char>(s[end]))) ++end;
    if (end >= s.size() || s[end] != '1') fail(formula, "only '- 1' may be subtracted");
    p.intercept = false;
    s.replace(at, end + 1 - at, "+ 0");
  }
  for (const auto& part : splitTopLevel(s, '+')) {
    if (part.empty()) fail(formula, "an empty term");
    if (part == "1") continue;
    if (part == "0") {
      p.intercept = false;
      continue;
    }
    if (part.find('*') != std::string::npos) addCrossing(p.terms, factorNames(formula, part, '*'));
    else addTerm(p.terms, factorNames(formula, part, ':'));
  }
  std::stable_sort(p.terms.begin(), p.terms.end(), [](const ModelTerm& a, const ModelTerm& b) { return a.size() < b.size(); });
  return p;
}

void parseRandomTerm(std::string_view formula, const std::string& part, std::vector<RandomTerm>& out) {
  const std::string inner = trim(std::string_view(part).substr(1, part.size() - 2));
  if (inner.find("||") != std::string::npos) fail(formula, "'||' (uncorrelated random effects) is not supported; write separate terms");
  const auto bar = splitTopLevel(inner, '|');
  if (bar.size() != 2) fail(formula, "'" + part + "' is not a random-effects term (expr | group)");
  const LinearPredictor expression = parsePredictor(formula, bar[0]);
  if (!expression.intercept && expression.terms.empty()) fail(formula, "'" + part + "' has no random effects");
  const std::string group = bar[1];
  if (group.find('/') != std::string::npos) {
    const auto nested = factorNames(formula, group, '/');
    // lme4's expandSlash names the inner factors first: school/class gives school and class:school.
    for (std::size_t k = 1; k <= nested.size(); ++k)
      out.push_back({expression, std::vector<std::string>(nested.rend() - static_cast<std::ptrdiff_t>(k), nested.rend())});
    return;
  }
  out.push_back({expression, factorNames(formula, group, ':')});
}

}  // namespace

std::vector<std::string> ModelFormula::variables() const {
  std::vector<std::string> out;
  const auto add = [&](const LinearPredictor& p) {
    for (const auto& term : p.terms)
      for (const auto& v : term)
        if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  };
  add(fixed);
  for (const auto& r : random) add(r.expression);
  return out;
}

ModelFormula parseModelFormula(std::string_view text) {
  ModelFormula f;
  f.text = trim(text);
  const auto tilde = f.text.find('~');
  if (tilde == std::string::npos) fail(text, "no '~' between the response and the terms");
  std::string response = trim(std::string_view(f.text).substr(0, tilde));
  if (response.rfind("log(", 0) == 0 && response.back() == ')') {
    f.logResponse = true;
    response = trim(std::string_view(response).substr(4, response.size() - 5));
  }
  if (!isName(response)) fail(text, "the response '" + response + "' is not a column (or log(column))");
  f.response = unquote(response);
  std::string fixedText;
  for (const auto& part : splitTopLevel(std::string_view(f.text).substr(tilde + 1), '+')) {
    if (part.size() >= 2 && part.front() == '(' && part.back() == ')' && part.find('|') != std::string::npos)
      parseRandomTerm(text, part, f.random);
    else
      fixedText += (fixedText.empty() ? "" : " + ") + part;
  }
  f.fixed = parsePredictor(text, fixedText.empty() ? "1" : fixedText);
  if (f.random.empty()) fail(text, "no random-effects term (expr | group): use tlab stats anova or ttest for fixed effects only");
  return f;
}

std::string termLabel(const ModelTerm& term) {
  if (term.empty()) return "(Intercept)";
  std::string out;
  for (const auto& v : term) out += (out.empty() ? "" : ":") + v;
  return out;
}

std::string groupingLabel(const std::vector<std::string>& grouping) { return termLabel(grouping); }

}  // namespace tlab::analysis
