// SPDX-License-Identifier: BSD-3-Clause
// The journal of a study (io/journal.hpp): resume, torn last lines, every line checked
// (checksum, index, duplicates, the caller's check), old and foreign journals, the lock that
// keeps a second writer out.
#include "flexrock/io/journal.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "flexrock/core/error.hpp"
#include "support/expect_error.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

class JournalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_journal_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "out.csv.partial").string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  void write(const std::string& text) { std::ofstream(path_, std::ios::binary) << text; }
  // a journal of 10 runs with the lines of runs 5 and 2
  void make_two() {
    Journal j(path_, "sweep", 42, 10);
    j.append(5, "5,a,b");
    j.append(2, "2,c,d");
  }
  std::string header() const { return journal_header("sweep", 42, 10); }
  fs::path dir_;
  std::string path_;
};

TEST_F(JournalTest, ResumesAndDropsATornLastLine) {
  make_two();
  EXPECT_EQ(read(path_), header() + "\n" + journal_line(header(), 5, "5,a,b") + "\n" +
                             journal_line(header(), 2, "2,c,d") + "\n");
  // a kill in the middle of a line
  std::ofstream(path_, std::ios::app) << "7 0123456789abcdef 7,half a li";
  {
    Journal j(path_, "sweep", 42, 10);
    EXPECT_EQ(j.resumed(), 2u);
    ASSERT_EQ(j.finished().size(), 2u);
    EXPECT_EQ(j.finished().at(5), "5,a,b");
    EXPECT_EQ(j.finished().at(2), "2,c,d");
    // the torn line is gone from the file, not only from memory
    EXPECT_EQ(read(path_).find("half"), std::string::npos);
    j.append(7, "7,e,f");
  }
  EXPECT_EQ(Journal(path_, "sweep", 42, 10).finished().size(), 3u);
  Journal(path_, "sweep", 42, 10).remove();
  EXPECT_FALSE(fs::exists(path_));
}

TEST_F(JournalTest, AJournalKilledBeforeItsHeaderStartsAfresh) {
  write("# flexrock swe");
  Journal j(path_, "sweep", 42, 10);
  EXPECT_TRUE(j.finished().empty());
  EXPECT_EQ(read(path_), header() + "\n");
}

TEST_F(JournalTest, EveryKindOfCorruptLineIsRefusedWithItsLineNumber) {
  make_two();
  const std::string good = read(path_);
  const std::string line5 = journal_line(header(), 5, "5,a,b");
  auto with_line2 = [&](const std::string& replacement) {
    std::string text = good;
    text.replace(text.find(line5), line5.size(), replacement);
    write(text);
  };
  auto refused = [&](std::initializer_list<std::string> parts) {
    test::expect_input_error([&] { Journal(path_, "sweep", 42, 10); }, parts);
  };
  // a changed value, keeping the old checksum
  std::string changed = line5;
  changed.back() = 'x';
  with_line2(changed);
  refused({path_ + ":2:", "checksum", "delete that line"});
  // a NUL byte
  std::string nul = line5;
  nul[nul.size() - 2] = '\0';
  with_line2(nul);
  refused({path_ + ":2:", "NUL"});
  // no checksum at all, as a v1 line
  with_line2("5,a,b");
  refused({path_ + ":2:", "16 hex digits"});
  // an index out of range, with a checksum that matches
  with_line2(journal_line(header(), 12, "12,a,b"));
  refused({path_ + ":2:", "out of range"});
  // a moved line: the checksum binds the index
  std::string moved = line5;
  moved[0] = '4';
  with_line2(moved);
  refused({path_ + ":2:", "checksum"});
  // a line of another journal (other inputs): its checksum starts elsewhere
  with_line2(journal_line(journal_header("sweep", 43, 10), 5, "5,a,b"));
  refused({path_ + ":2:", "checksum"});
  // the same run twice: equal lines are harmless, different ones are refused
  write(good + journal_line(header(), 5, "5,a,b") + "\n");
  EXPECT_EQ(Journal(path_, "sweep", 42, 10).finished().size(), 2u);
  write(good + journal_line(header(), 5, "5,a,z") + "\n");
  refused({path_ + ":4:", "run 5 twice", "first at line 2"});
  // nothing was changed by a refusal
  EXPECT_EQ(read(path_), good + journal_line(header(), 5, "5,a,z") + "\n");
}

TEST_F(JournalTest, TheCallersCheckSeesEveryLine) {
  make_two();
  const JournalCheck check = [](std::size_t index, const std::string& line) -> std::string {
    return line.starts_with(std::to_string(index) + ",") ? "" : "the body does not match";
  };
  EXPECT_EQ(Journal(path_, "sweep", 42, 10, check).finished().size(), 2u);
  std::ofstream(path_, std::ios::app) << journal_line(header(), 3, "4,a,b") << "\n";
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 10, check); },
                           {path_ + ":4:", "run 3: the body does not match"});
}

TEST_F(JournalTest, OldForeignAndUnknownJournalsAreRefused) {
  // a journal of the previous format, without checksums: refused, with what to do
  const std::string v1 = "# flexrock sweep journal v1 manifest=000000000000002a runs=10\n5,a,b\n";
  write(v1);
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 10); },
                           {"earlier flexrock", "no checksums", "delete it"});
  EXPECT_EQ(read(path_), v1);
  // other inputs, another run count, another kind
  fs::remove(path_);
  make_two();
  const std::string two = read(path_);
  test::expect_input_error([&] { Journal(path_, "sweep", 43, 10); },
                           {path_ + ":1:", "other inputs", "delete it"});
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 11); }, {"another run count"});
  test::expect_input_error([&] { Journal(path_, "spectrum", 42, 10); }, {"other inputs"});
  EXPECT_EQ(read(path_), two);
  // a file that is not a journal is left alone
  write("index,body\n1,2\n");
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 10); }, {"not a flexrock journal"});
  EXPECT_EQ(read(path_), "index,body\n1,2\n");
}

TEST_F(JournalTest, AForeignJournalWithNoRunInItStartsAfresh) {
  // nothing to lose: e.g. a study refused before its first run, then corrected
  write(journal_header("sweep", 43, 10) + "\n");
  Journal j(path_, "sweep", 42, 10);
  EXPECT_TRUE(j.finished().empty());
  EXPECT_EQ(read(path_), header() + "\n");
}

TEST_F(JournalTest, ASecondWriterIsRefusedWhileTheFirstHoldsTheJournal) {
  Journal first(path_, "sweep", 42, 10);
  first.append(1, "1,a,b");
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 10); },
                           {path_, "another flexrock process", "-o"});
  // another process, as a second `flexrock sweep` on the same output would be
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    try {
      Journal second(path_, "sweep", 42, 10);
    } catch (const InputError& e) {
      ::_exit(std::string(e.what()).find("another flexrock process") != std::string::npos ? 3 : 4);
    } catch (...) {
      ::_exit(5);
    }
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  // the refused writers changed nothing
  EXPECT_EQ(read(path_), header() + "\n" + journal_line(header(), 1, "1,a,b") + "\n");
  first.remove();
  // released: the next one may start
  Journal again(path_, "sweep", 42, 10);
  EXPECT_TRUE(again.finished().empty());
}

TEST_F(JournalTest, OnlyARegularFileCanBeAJournal) {
  fs::create_directory(path_);
  EXPECT_ANY_THROW(Journal(path_, "sweep", 42, 10));
  fs::remove(path_);
  ASSERT_EQ(::mkfifo(path_.c_str(), 0600), 0);
  test::expect_input_error([&] { Journal(path_, "sweep", 42, 10); }, {"not a regular file"});
}

}  // namespace
}  // namespace flexrock::io
