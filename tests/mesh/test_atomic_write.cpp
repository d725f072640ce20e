// Writes through a temporary file (core/atomic_file.h), issue 21 items 1 and
// 15: a symlink planted at the temporary name a writer used to choose
// (NAME.tmp<PID>) or at the output's own name never leads the write to
// another file; the output gets an ordinary new file's permissions.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/mesh/write_surface.h"
#include "igaprep/models/shapes.h"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(AtomicWrite, APlantedSymlinkIsNeverFollowed) {
  const fs::path dir = fresh_folder("test_atomic_symlink");
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "precious\n";
  const fs::path out = dir / "out.off";
  // Links at the names a writer of this process could predict.
  for (const std::string& suffix : std::vector<std::string>{".tmp" + std::to_string(::getpid()), ".tmp"})
    fs::create_symlink(victim, out.string() + suffix);
  igaprep::mesh::write_surface(out.string(), igaprep::models::make_ellipsoid(1, 1, 1, 1));
  EXPECT_EQ(slurp(victim), "precious\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out)));
  EXPECT_EQ(slurp(out).rfind("OFF", 0), 0u);

  // A link at the output's own name is replaced, its target left alone.
  const fs::path linked = dir / "linked.txt";
  fs::create_symlink(victim, linked);
  igaprep::write_file_atomically(linked.string(), [](std::ostream& o) { o << "new\n"; });
  EXPECT_EQ(slurp(victim), "precious\n");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(linked)));
  EXPECT_EQ(slurp(linked), "new\n");

  // Nothing is left behind but the outputs, the victim and the planted links.
  int temporaries = 0;
  for (const auto& e : fs::directory_iterator(dir))
    temporaries += e.path().filename().string().find(".tmp") != std::string::npos && !fs::is_symlink(e.symlink_status());
  EXPECT_EQ(temporaries, 0);
}

TEST(AtomicWrite, TheOutputHasAnOrdinaryNewFilesPermissions) {
  const fs::path dir = fresh_folder("test_atomic_mode");
  const mode_t old = ::umask(022);
  igaprep::write_file_atomically((dir / "a.txt").string(), [](std::ostream& o) { o << "a\n"; });
  ::umask(old);
  struct stat st {};
  ASSERT_EQ(::stat((dir / "a.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST(AtomicWrite, AFailedWriteLeavesNoTemporaryAndTheOldFile) {
  const fs::path dir = fresh_folder("test_atomic_fail");
  const fs::path out = dir / "keep.txt";
  std::ofstream(out) << "old\n";
  EXPECT_THROW(igaprep::write_file_atomically(out.string(),
                                              [](std::ostream&) { throw igaprep::bad_input("stop"); }),
               igaprep::Error);
  EXPECT_EQ(slurp(out), "old\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  // A folder that does not exist is bad input naming the file.
  try {
    igaprep::write_file_atomically((dir / "no" / "x.txt").string(), [](std::ostream& o) { o << "x"; });
    ADD_FAILURE() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write '"), std::string::npos) << e.what();
  }
}

// A temporary that a killed writer left (NAME.tmp<pid>-XXXXXX) is removed by
// the next write of the same output; one of a process that runs stays.
TEST(AtomicWrite, ATemporaryOfAnEndedProcessIsRemovedByTheNextWrite) {
  const fs::path dir = fresh_folder("atomic_stale");
  const fs::path out = dir / "result.h5";
  std::ofstream(dir / "result.h5.tmp99999999-Ab12Cd") << "left by a killed solve";  // no such pid
  std::ofstream(dir / "result.h5.tmp1-Ab12Cd") << "a running writer's";                // pid 1 runs
  igaprep::write_file_atomically(out.string(), [](std::ostream& o) { o << "new"; });
  EXPECT_EQ(slurp(out), "new");
  EXPECT_FALSE(fs::exists(dir / "result.h5.tmp99999999-Ab12Cd"));
  EXPECT_TRUE(fs::exists(dir / "result.h5.tmp1-Ab12Cd"));
}
