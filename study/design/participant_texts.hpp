#pragma once
// ParticipantTexts: every word tlab shows participants, as one table of keys ("button.continue",
// "answer.layer-number") with their text in the experiment's language. The keys and their English
// text are study/design/texts/en.toml; each shipped translation (de.toml, fr.toml) has every key.
// An experiment picks a language (`language = "de"`) and overrides any key in its [text] table;
// a language that is not shipped (or a key it lacks) shows the English text until [text] gives it,
// and `tlab design` warns about each such key. Front ends ask this table and print no words of
// their own: the window, the browser page (which gets the table as JSON) and the server's pages.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace tlab::study {

class ParticipantTexts {
 public:
  // English: every key with its text from en.toml.
  ParticipantTexts();
  // The shipped translation of `language` ("en", "de", "fr"); keys it lacks (every key, for a
  // language that is not shipped) keep their English text and are listed by untranslated().
  explicit ParticipantTexts(const std::string& language);

  const std::string& language() const { return language_; }
  // The text of `key`; throws std::out_of_range naming a key that is not in the table.
  const std::string& text(const std::string& key) const;
  // The text of `key` with each {name} replaced by values[name].
  std::string format(const std::string& key, const std::map<std::string, std::string>& values = {}) const;
  // The singular or plural form (key + ".one" / ".other", by the language's rule for n) with {n}
  // replaced by n and each {name} by values[name].
  std::string count(const std::string& key, long n, std::map<std::string, std::string> values = {}) const;
  // The same for an amount that need not be whole ("2.5 minutes", "2,5 Minuten").
  std::string amount(const std::string& key, double value) const;
  // A number as the language writes it ("2.5", "2,5").
  std::string number(double value) const;

  // The same table in another language, with the same [text] overrides.
  ParticipantTexts inLanguage(const std::string& language) const;

  bool has(const std::string& key) const { return texts_.count(key) > 0; }
  // The {values} tlab fills into `key`: those of its English text, and for a plural form
  // ("trials_left.one") those of the other form too. Every shipped language uses the same.
  static std::set<std::string> valuesOf(const std::string& key);
  // An experiment file's [text] value for `key`; throws std::out_of_range for a key not in the table.
  void set(const std::string& key, const std::string& value);
  // Keys shown in English because the language has no text for them and [text] gave none.
  std::vector<std::string> untranslated() const;
  const std::map<std::string, std::string>& entries() const { return texts_; }

 private:
  std::string language_ = "en";
  std::map<std::string, std::string> texts_;
  std::map<std::string, bool> translated_;  // key -> whether its text is in language_ (or set by [text])
  std::map<std::string, std::string> overrides_;  // [text]
};

// The {name} placeholders of a text as the page fills them (letters and '_' between braces).
std::set<std::string> placeholdersOf(const std::string& text);

// The languages tlab ships a translation for ("de", "en", "fr").
std::vector<std::string> shippedLanguages();
// The shipped table of `language` as written in its file (key -> text); empty if not shipped.
std::map<std::string, std::string> shippedTexts(const std::string& language);

}  // namespace tlab::study
