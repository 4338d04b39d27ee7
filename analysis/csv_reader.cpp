// Why a hand-written parser: of the libraries installed on the Debian 12 build machines, the only
// CSV-capable one is Boost.Tokenizer's escaped_list_separator, which is not RFC 4180: it treats a
// backslash as an escape character, turns a doubled quote "" inside a quoted field into nothing
// (it just toggles the quote state twice), and works line by line, so quoted line breaks are
// impossible. libcsv (libcsv-dev) would do, but is not installed and would add a dependency for
// ~100 lines. RFC 4180 is a small regular language, parsed here by a four-state machine.
#include "analysis/csv_reader.hpp"
#include "core/file_text.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace {

struct CsvRecord {
  std::vector<std::string> fields;
  std::size_t line = 0;  // line on which the record starts
};

// RFC 4180 section 2 grammar as a state machine over characters.
class CsvParser {
 public:
  CsvParser(std::string_view text, const std::string& source) : text_(text), source_(source) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);  // UTF-8 byte order mark
  }

  // Next record, or false at the end of input. Blank lines are skipped.
  bool next(CsvRecord& record) {
    record.fields.clear();
    while (pos_ < text_.size() && isLineBreakAt(pos_)) consumeLineBreak();
    if (pos_ >= text_.size()) return false;
    record.line = line_;
    Cursor cur{record, {}, State::FieldStart, line_, false};
    while (pos_ < text_.size()) {
      step(cur, text_[pos_]);
      if (cur.recordEnded) return true;
    }
    if (cur.state == State::Quoted)
      throw AnalysisError(source_ + ":" + std::to_string(cur.quoteLine) +
                          ": quoted field is never closed (missing \")");
    record.fields.push_back(std::move(cur.field));
    return true;
  }

 private:
  enum class State { FieldStart, Unquoted, Quoted, QuoteInQuoted };

  // The record being read: its fields so far, the field being read and the machine's state.
  struct Cursor {
    CsvRecord& record;
    std::string field;
    State state;
    std::size_t quoteLine;  // where the open quote started
    bool recordEnded;
  };

  // After a field: a comma starts the next field, a line break ends the record. Returns whether
  // the character at pos_ was such a delimiter (and consumes it).
  bool delimiter(Cursor& cur, char c) {
    if (c == ',') {
      cur.record.fields.push_back(std::move(cur.field));
      cur.field.clear();
      cur.state = State::FieldStart;
      ++pos_;
      return true;
    }
    if (!isLineBreakAt(pos_)) return false;
    consumeLineBreak();
    cur.record.fields.push_back(std::move(cur.field));
    cur.recordEnded = true;
    return true;
  }

  // One character c at pos_, by the state it arrives in.
  void step(Cursor& cur, char c) {
    switch (cur.state) {
      case State::FieldStart:
        if (c == '"') {
          cur.state = State::Quoted;
          cur.quoteLine = line_;
          ++pos_;
          return;
        }
        cur.state = State::Unquoted;
        return;  // re-read c as part of an unquoted field
      case State::Unquoted:
        if (delimiter(cur, c)) return;
        if (c == '"')
          throw AnalysisError(source_ + ":" + std::to_string(line_) +
                              ": stray double quote inside an unquoted field (quote the whole "
                              "field and double the quote: \"\")");
        cur.field.push_back(c);
        ++pos_;
        return;
      case State::Quoted:
        if (c == '"') {
          cur.state = State::QuoteInQuoted;
          ++pos_;
          return;
        }
        if (c == '\n') ++line_;
        cur.field.push_back(c);
        ++pos_;
        return;
      case State::QuoteInQuoted:
        if (c == '"') {  // "" is an escaped quote
          cur.field.push_back('"');
          cur.state = State::Quoted;
          ++pos_;
          return;
        }
        if (delimiter(cur, c)) return;
        throw AnalysisError(source_ + ":" + std::to_string(line_) + ": unexpected character '" +
                            std::string(1, c) + "' after a closing double quote");
    }
  }

  bool isLineBreakAt(std::size_t i) const { return text_[i] == '\n' || text_[i] == '\r'; }
  void consumeLineBreak() {
    if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

}  // namespace

Table parseCsv(std::string_view text, const std::string& source) {
  CsvParser parser(text, source);
  CsvRecord header;
  if (!parser.next(header)) throw AnalysisError(source + ": empty CSV file (no header row)");
  for (std::size_t i = 0; i < header.fields.size(); ++i)
    if (header.fields[i].empty())
      throw AnalysisError(source + ":" + std::to_string(header.line) + ": header field " +
                          std::to_string(i + 1) + " is empty");
  Table table(source, header.fields);
  CsvRecord record;
  while (parser.next(record)) table.addRow(std::move(record.fields), record.line);
  return table;
}

Table readCsvFile(const std::string& path) {
  const auto text = core::readFileText(path);
  if (!text) throw AnalysisError(path + ": cannot open file");
  return parseCsv(*text, path);
}

}  // namespace tlab::analysis
