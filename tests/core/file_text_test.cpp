// tlab::core::readFileText: the bytes of a file exactly (NUL, CR, invalid UTF-8), nullopt for a missing one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/file_text.hpp"

TEST(FileText, ReadsEveryByteAndSaysWhenAFileIsMissing) {
  const auto path = std::filesystem::temp_directory_path() / ("tlab_file_text_" + std::to_string(::getpid()) + ".bin");
  const std::string bytes("a\0b\r\n\xff\xfe end", 11);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(tlab::core::readFileText(path.string()), bytes);
  std::filesystem::remove(path);
  EXPECT_FALSE(tlab::core::readFileText(path.string()).has_value());
}

TEST(FileText, TheLastNonEmptyLineIsWhatALogSaysLast) {
  EXPECT_EQ(tlab::core::lastNonEmptyLine("frame 1\nerror: no GL\n  \n\t\r\n"), "error: no GL");
  EXPECT_EQ(tlab::core::lastNonEmptyLine("one line"), "one line");
  EXPECT_EQ(tlab::core::lastNonEmptyLine(" \n\n"), "");
}
