#pragma once
// The tables export and analysis read (Store::exportTable, analysisRecords, sessionModes,
// formAnswers, stimulusSummary, stimulusExamples, liveTrials, trialFrames), written once in SQL that SQLite and PostgreSQL
// both run, over a small query interface each store implements. One copy of the SQL and of the
// cell formatting keeps `tlab export` byte for byte the same from either store.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "study/store/store.hpp"

namespace tlab::study {

// One row of a query result, as the tables read it.
class ResultRow {
 public:
  virtual ~ResultRow() = default;
  virtual bool isNull(int column) const = 0;  // 0-based columns
  virtual std::int64_t integer(int column) const = 0;
  virtual double real(int column) const = 0;
  // The value as text, as SQLite writes it: integers in decimal, REAL values as storedRealText.
  virtual std::string text(int column) const = 0;
};

// Runs one reading statement; `?1`, where the SQL holds it, is `parameter`.
class TableQueries {
 public:
  virtual ~TableQueries() = default;
  virtual void forEachRow(const std::string& sql, const std::string& parameter, const std::function<void(const ResultRow&)>& row) = 0;
};

// SQLite's text of a REAL value ("%!.15g": 3.0, 0.1, 1.0e+20), which the exports have always
// written for REAL cells; PostgreSQL's own text of a double differs (3, 1e+20), so it uses this.
std::string storedRealText(double value);

namespace store_tables {

DataTable exportTable(TableQueries& q, ExportTable table, const Experiment& experiment);
std::vector<AnalysisRecord> analysisRecords(TableQueries& q, const std::string& experimentId, const std::string& dependentVariable);
std::vector<std::map<std::string, int>> sessionModes(TableQueries& q, const std::string& experimentId);
std::vector<StoredAnswer> formAnswers(TableQueries& q, const std::string& experimentId);
DataTable stimulusSummary(TableQueries& q, const std::string& experimentId);
DataTable stimulusExamples(TableQueries& q, const std::string& experimentId);
DataTable liveTrials(TableQueries& q, const std::string& experimentId);
DataTable trialFrames(TableQueries& q, std::int64_t trial);

}  // namespace store_tables

}  // namespace tlab::study
