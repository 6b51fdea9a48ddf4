// Temporary files and signals (tools/support/temporaries.hpp): a registered name is removed by
// remove_temporaries() until it is released, and a writer ended by a signal in the middle of its
// file leaves nothing beside its target. Each signal is raised in a child process (fork), which
// ends as the tool would; the parent reads its status and the directory.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "temporaries.hpp"
#include "tools/scratch_dir.hpp"
#include "writer.hpp"

namespace ridt::io {
namespace {

namespace fs = std::filesystem;

class Temporaries : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::fresh_test_dir("ridt_temporaries"); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t files() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}));
  }

  /// The wait status of a child that runs `body` (which should not return: it exits 0 if it does).
  static int in_child(const std::function<void()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      body();
      ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
  }

  fs::path dir_;
};

TEST_F(Temporaries, RegisteredNamesAreRemovedUntilReleased) {
  for (const char* name : {"a.tmp", "b.tmp", "c.tmp"}) std::ofstream(path(name)) << "x";
  TemporaryName a(path("a.tmp")), b(path("b.tmp"));
  {
    TemporaryName c(path("c.tmp"));  // released when it goes
  }
  b.release();
  remove_temporaries();
  EXPECT_FALSE(fs::exists(path("a.tmp")));
  EXPECT_TRUE(fs::exists(path("b.tmp")));
  EXPECT_TRUE(fs::exists(path("c.tmp")));
  // Moved, the name stays registered once; a released slot is taken again.
  std::ofstream(path("d.tmp")) << "x";
  TemporaryName d(path("d.tmp"));
  TemporaryName moved = std::move(d);
  d.release();  // nothing: it holds no name now
  remove_temporaries();
  EXPECT_FALSE(fs::exists(path("d.tmp")));
}

// A file half written when SIGTERM or SIGINT comes: the process ends by that signal, and neither
// the target nor its temporary file is left.
TEST_F(Temporaries, ASignalMidFileLeavesNothing) {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    SCOPED_TRACE(sig);
    const int status = in_child([&] {
      ::signal(sig, SIG_DFL);  // the test run's own may be ignored (nohup, a background job)
      end_on_signals("bus\n");
      Writer w(path("out.ele"));
      for (int k = 0; k < 200000; ++k) w.put("12345 67890 13579\n");  // some of it flushed
      if (files() != 1) ::_exit(10);  // the temporary file, and nothing else
      ::raise(sig);
      ::_exit(11);
    });
    ASSERT_TRUE(WIFSIGNALED(status)) << status;
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_EQ(files(), 0u);
  }
}

// SIGBUS (an input mapped and cut short): the message, status 2, nothing left.
TEST_F(Temporaries, ABusErrorExitsWithStatusTwoAndLeavesNothing) {
  const int status = in_child([&] {
    end_on_signals("ridt: error: an input file could not be read to its end\n");
    Writer w(path("out.node"));
    w.put("1 2 3\n");
    ::raise(SIGBUS);
    ::_exit(11);
  });
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_EQ(files(), 0u);
}

// A file past the size limit: no SIGXFSZ death, but the writer's error (EFBIG), and its file
// removed.
TEST_F(Temporaries, AFilePastTheSizeLimitIsAnError) {
  const int status = in_child([&] {
    end_on_signals("bus\n");
    const rlimit small{1 << 16, 1 << 16};
    if (::setrlimit(RLIMIT_FSIZE, &small) != 0) ::_exit(12);
    try {
      Writer w(path("big.ele"));
      for (int k = 0; k < 100000; ++k) w.put("12345 67890 13579\n");
      w.commit();
    } catch (const IoError& e) {
      ::_exit(std::string(e.what()).find("File too large") != std::string::npos ? 20 : 21);
    }
    ::_exit(13);
  });
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 20);
  EXPECT_EQ(files(), 0u);
}

}  // namespace
}  // namespace ridt::io
