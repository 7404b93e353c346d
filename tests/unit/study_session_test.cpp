// SPDX-License-Identifier: BSD-3-Clause
// Study sessions (io/study_session.hpp): every state the public API reaches ends in an exception
// that says what to do, never an abort; finish() before the runs are done keeps the journal, and
// the session goes on from it.
#include "flexrock/io/study_session.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "flexrock/io/study_files.hpp"

namespace flexrock::io {
namespace {

namespace fs = std::filesystem;

class StudySession : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexrock_study_session_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // the message of what f throws as std::runtime_error ("" when it does not)
  template <class F>
  static std::string runtime_error_of(F f) {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

const char* kBody = "[body]\ntype = \"rigid_block\"\nwidth = 0.4\nheight = 2.0\nmass = 100.0\n";

TEST_F(StudySession, SweepFinishBeforeTheRunsIsAnErrorThatSaysToRunFirst) {
  write("b.toml", kBody);
  write("r.dat", "0.0\n0.1\n-0.2\n0.3\n0.0\n");
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = [0.5, 1.0, 2.0]\n");
  const std::string out = (dir_ / "s.csv").string();
  {
    SweepSession s(load_sweep_manifest(m), out);
    // never run
    std::string e = runtime_error_of([&] { s.finish(); });
    EXPECT_NE(e.find("0 of 3 runs are finished"), std::string::npos) << e;
    EXPECT_NE(e.find("call run() first"), std::string::npos) << e;
    EXPECT_NE(e.find(out + ".partial"), std::string::npos) << e;
    // a run stopped before it started one
    const std::atomic<bool> stop{true};
    study::RunOptions o;
    o.threads = 1;
    o.cancel = &stop;
    s.run(o);
    e = runtime_error_of([&] { s.finish(); });
    EXPECT_NE(e.find("call run() first"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(out));
    // and then run on
    o.cancel = nullptr;
    s.run(o);
    EXPECT_EQ(s.finish().size(), 3u);
  }
  EXPECT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

TEST_F(StudySession, SpectrumFinishBeforeTheCellsIsAnErrorThatSaysToRunFirst) {
  const std::string p = write("s.toml", std::string(kBody) +
                                            "[spectrum]\namplitudes = [2.0, 4.0]\n"
                                            "frequencies = [2.0, 4.0]\nfree_periods = 1\n");
  const std::string out = (dir_ / "c.csv").string(), boundary = (dir_ / "b.csv").string();
  {
    SpectrumSession s(load_spectrum_file(p), out, boundary);
    const std::string e = runtime_error_of([&] { s.finish(); });
    EXPECT_NE(e.find("0 of 4 cells are finished"), std::string::npos) << e;
    EXPECT_NE(e.find("call run() first"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(out));
    study::RunOptions o;
    o.threads = 1;
    s.run(o);
    EXPECT_EQ(s.finish().cells.size(), 4u);
  }
  EXPECT_TRUE(fs::exists(out));
  EXPECT_TRUE(fs::exists(boundary));
}

TEST_F(StudySession, RunTwiceJournalsEachRunOnceAndNothingRunsAfterFinish) {
  write("b.toml", kBody);
  write("r.dat", "0.0\n0.1\n-0.2\n0.3\n0.0\n");
  const std::string m = write("m.toml",
                              "[[body]]\nfile = \"b.toml\"\n"
                              "[[record]]\nfile = \"r.dat\"\nformat = \"single_column\"\n"
                              "dt = 0.01\nunits = \"g\"\nname = \"rec\"\n"
                              "[scales]\nfactors = [0.5, 1.0, 2.0]\n");
  const std::string p = write("s.toml", std::string(kBody) +
                                            "[spectrum]\namplitudes = [2.0, 4.0]\n"
                                            "frequencies = [2.0, 4.0]\nfree_periods = 1\n");
  const std::string out = (dir_ / "s.csv").string(), cells = (dir_ / "c.csv").string();
  const std::string boundary = (dir_ / "b.csv").string();
  study::RunOptions o;
  o.threads = 1;
  // run() twice, then left without finish(): the next session resumes every run from a journal
  // that holds each once (a run journaled twice is refused as a duplicate)
  {
    SweepSession s(load_sweep_manifest(m), out);
    s.run(o);
    s.run(o);
  }
  {
    SpectrumSession s(load_spectrum_file(p), cells, boundary);
    s.run(o);
    s.run(o);
  }
  SweepSession sweep(load_sweep_manifest(m), out);
  EXPECT_EQ(sweep.resumed(), 3u);
  EXPECT_EQ(sweep.finish().size(), 3u);
  SpectrumSession spectrum(load_spectrum_file(p), cells, boundary);
  EXPECT_EQ(spectrum.resumed(), spectrum.runs());
  EXPECT_EQ(spectrum.finish().cells.size(), 4u);
  // after finish() the sessions are over: run() and finish() say so
  for (const std::string& e :
       {runtime_error_of([&] { sweep.run(o); }), runtime_error_of([&] { sweep.finish(); }),
        runtime_error_of([&] { spectrum.run(o); }), runtime_error_of([&] { spectrum.finish(); })}) {
    EXPECT_NE(e.find("after finish(): the session is over"), std::string::npos) << e;
    EXPECT_NE(e.find("open a new session"), std::string::npos) << e;
  }
  EXPECT_FALSE(fs::exists(out + ".partial"));
}

}  // namespace
}  // namespace flexrock::io
