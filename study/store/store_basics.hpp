#pragma once
// What every store shares: its error type and how it is opened.
#include <stdexcept>
#include <string>

namespace tlab::study {

// How a store is opened: Create (made if missing), Write (must exist), Read (never writes a byte:
// readers — analyze, export, report — work on read-only files, folders and media).
enum class OpenMode { Create, Write, Read };

// A storage failure. Messages from SQLite say what happened and what to do ("... is full: free
// space, then continue with --resume"); `code` is the store's own code (SQLite's extended result code; 0: none).
class StoreError : public std::runtime_error {
 public:
  explicit StoreError(const std::string& message, int code = 0) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_ = 0;
};

}  // namespace tlab::study
