// A program file is read where it lies (file_text.hpp): a private copy mapped, so the text is
// the file as it was when read, whatever happens to the file afterwards; a pipe is read the
// same way; and the pages of the mapping resident in the process stay within the chunks read
// last through every pass over the text, however long the text (measured in /proc/self/smaps).

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <thread>

#include "../test_support.hpp"
#include "interp/base/diagnostic.hpp"
#include "interp/text/control_family.hpp"
#include "interp/text/file_text.hpp"
#include "interp/text/program.hpp"
#include "interp/text/machine_evidence.hpp"

namespace lathesim::interp {
namespace {

namespace fs = std::filesystem;

// A path of this test's own in the temporary directory, removed after it.
class TempPath {
 public:
  explicit TempPath(const std::string& name)
      : path_(fs::temp_directory_path() / fmt::format("lathesim_file_text_{}_{}", ::getpid(), name)) {}
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;
  ~TempPath() { fs::remove(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  ASSERT_TRUE(out.flush());
}

// The bytes of the mapping starting at `data` resident in this process: its Rss in smaps.
std::size_t residentBytes(const char* data) {
  std::ifstream smaps("/proc/self/smaps");
  const auto wanted = reinterpret_cast<std::uintptr_t>(data);
  bool inMapping = false;
  for (std::string line; std::getline(smaps, line);) {
    unsigned long from = 0, to = 0;
    if (std::sscanf(line.c_str(), "%lx-%lx ", &from, &to) == 2) {
      inMapping = from == wanted;
    } else if (inMapping && line.starts_with("Rss:")) {
      return std::stoul(line.substr(4)) << 10;
    }
  }
  ADD_FAILURE() << "no mapping starts at " << static_cast<const void*>(data);
  return 0;
}

// Every page of `text` read without saying where: all of it becomes resident.
void touchEveryPage(std::string_view text) {
  for (std::size_t at = 0; at < text.size(); at += 1024) (void)*static_cast<const volatile char*>(&text[at]);
}

TEST(FileText, IsTheFileAsItWasWhenRead) {
  const TempPath file("as_read.nc");
  const std::string text = "O0001\nG00 X40 Z2\nG01 Z-20 F0.1\nM30\n";
  writeFile(file.path(), text);
  const FileText read = FileText::read(file.path());
  EXPECT_EQ(read.text().view(), text);
  // Rewritten in place and cut short: a mapping of the file itself would now read another
  // text, or die of SIGBUS past its new end.
  writeFile(file.path(), "M30\n");
  fs::resize_file(file.path(), 0);
  EXPECT_EQ(std::string(read.text().view()), text);
}

TEST(FileText, EmptyFile) {
  const TempPath file("empty.nc");
  writeFile(file.path(), "");
  EXPECT_TRUE(FileText::read(file.path()).text().view().empty());
}

TEST(FileText, ReadsAPipe) {
  const TempPath fifo("fifo.nc");
  ASSERT_EQ(::mkfifo(fifo.path().c_str(), 0600), 0) << std::strerror(errno);
  std::string text;
  for (int i = 0; i < 20000; ++i) text += fmt::format("G01 X{} Z-{} F0.1\n", 40 + i % 2, i % 50);  // past a pipe's buffer
  std::thread writer([&] { writeFile(fifo.path(), text); });
  const FileText read = FileText::read(fifo.path());
  writer.join();
  EXPECT_EQ(read.text().view(), text);
}

TEST(FileText, SaysWhyAFileCannotBeRead) {
  try {
    (void)FileText::read("/nonexistent/lathesim/program.nc");
    ADD_FAILURE() << "read a file that is not there";
  } catch (const std::system_error& error) {
    EXPECT_EQ(error.code().value(), ENOENT);
  }
  try {
    (void)FileText::read(fs::temp_directory_path());
    ADD_FAILURE() << "read a directory";
  } catch (const std::system_error& error) {
    EXPECT_EQ(error.code().value(), EISDIR);
  }
}

// A diagnostic of a mapped program quotes its line, as of a program held in memory.
TEST(FileText, DiagnosticsQuoteTheLinesOfAMappedProgram) {
  const TempPath file("diagnostic.nc");
  std::string text;
  for (int i = 0; i < 30000; ++i) text += "G01 X40 Z-1 F0.1\n";
  text += "G01 X40 Z-2 Q7\nM30\n";
  writeFile(file.path(), text);
  const FileText read = FileText::read(file.path());
  const InterpretResult result = interpret(read.text(), "diagnostic.nc", test::defaultOptions());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 30001);
  EXPECT_EQ(result.diagnostics[0].sourceLine, "G01 X40 Z-2 Q7");
}

// Samples the mapping's resident bytes as the moves come, keeping the most.
class ResidentSampler final : public MoveSink {
 public:
  explicit ResidentSampler(const char* mapping) : mapping_(mapping) {}
  void take(Move) override {
    if (++moves_ % 500 == 0) most = std::max(most, residentBytes(mapping_));
  }
  std::size_t most = 0;

 private:
  const char* mapping_;
  std::size_t moves_ = 0;
};

// Every pass over a mapped text leaves resident only the chunks it read last, for a text of
// 4 MB as for one of 16 MB: each pass starts with the whole text resident (touched without
// saying where), so a pass that let go of nothing, or only of what it said it read, ends
// with megabytes resident.
TEST(FileText, ResidentPagesStayBoundedHoweverLongTheText) {
  const std::size_t bound = FileText::kKeptChunks * FileText::kChunkBytes + (std::size_t{256} << 10);
  for (const std::size_t megabytes : {4, 16}) {
    SCOPED_TRACE(fmt::format("{} MB", megabytes));
    const TempPath file(fmt::format("long_{}.nc", megabytes));
    // Lines of about a kilobyte, most of it a comment, a label every thousand lines.
    const std::string comment(1000, 'x');
    std::string text = "G99 M03 S800\nG00 X40 Z2\n";
    for (int line = 0; text.size() < (megabytes << 20); ++line)
      text += fmt::format("{}G01 X{} Z-{} F0.1 ({})\n", line % 1000 == 0 ? fmt::format("N{} ", line / 1000 + 1) : "",
                          40 + line % 2, line % 50, comment);
    text += "M30\n";
    writeFile(file.path(), text);
    const FileText read = FileText::read(file.path());
    const PagedText paged = read.text();
    const char* mapping = paged.view().data();
    ASSERT_EQ(paged.view(), text);

    const auto afterPass = [&](const char* pass, auto run) {
      touchEveryPage(paged.view());
      ASSERT_GT(residentBytes(mapping), text.size() * 9 / 10) << "the measure sees the pages read";
      run();
      EXPECT_LE(residentBytes(mapping), bound) << pass;
    };
    afterPass("machine evidence and stated stock", [&] { EXPECT_FALSE(readMachineEvidence(paged).stock); });
    afterPass("foreign program", [&] { EXPECT_FALSE(recogniseForeignProgram(paged)); });
    afterPass("line quoted", [&] { EXPECT_EQ(lineOf(paged, 2), "G00 X40 Z2"); });
    afterPass("line starts", [&] { EXPECT_EQ(LineStarts(paged).lineOf(paged.view(), 2), "G00 X40 Z2"); });
    afterPass("lines quoted", [&] {
      Diagnostic last{Severity::Warning, "long.nc", static_cast<int>(std::count(text.begin(), text.end(), '\n')), 1, "", ""};
      quoteLines(paged, {&last});
      EXPECT_EQ(last.sourceLine, "M30");
    });
    afterPass("program read and searched", [&] {
      const Program program = readProgram(paged, false, Dialect::FanucA);
      EXPECT_GT(program.findSequence(1, program.blockCount() - 1).count, 0u);
    });
    afterPass("program run", [&] {
      ResidentSampler sampler(mapping);
      const InterpretResult result = interpret(paged, "long.nc", test::defaultOptions(), sampler);
      EXPECT_TRUE(result.ok());
      EXPECT_GT(sampler.most, 0u);
      EXPECT_LE(sampler.most, bound) << "while it ran";
    });
  }
}

}  // namespace
}  // namespace lathesim::interp
