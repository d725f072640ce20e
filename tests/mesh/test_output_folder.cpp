// core/output_folder.h: a set of outputs replaces the previous one at once,
// the folder's other files kept (here with the other core file tests).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/core/output_folder.h"

namespace {

namespace fs = std::filesystem;

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "output_folder" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Names in `folder` that hold `part`.
int entries_naming(const fs::path& folder, const std::string& part) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(folder)) n += e.path().filename().string().find(part) != std::string::npos;
  return n;
}

TEST(OutputFolder, ACommitReplacesTheOutputsAndKeepsTheOtherFiles) {
  const fs::path root = fresh("commit");
  const fs::path out = root / "out";
  fs::create_directories(out);
  ::chmod(out.c_str(), 0751);
  write(out / "model.h5", "old model");
  write(out / "notes.txt", "mine");
  igaprep::OutputFolder folder(out.string());
  EXPECT_TRUE(folder.atomic());
  EXPECT_EQ(fs::path(folder.staging()).parent_path(), root);  // beside it, on the same file system
  write(fs::path(folder.staging()) / "model.h5", "new model");
  write(fs::path(folder.staging()) / "report.json", "new report");
  EXPECT_EQ(read(out / "model.h5"), "old model");  // nothing changes before the commit
  folder.commit();
  EXPECT_EQ(read(out / "model.h5"), "new model");
  EXPECT_EQ(read(out / "report.json"), "new report");
  EXPECT_EQ(read(out / "notes.txt"), "mine");
  EXPECT_EQ(fs::status(out).permissions(), static_cast<fs::perms>(0751));
  EXPECT_EQ(entries_naming(root, ".igaprep-"), 0);
}

TEST(OutputFolder, WithoutACommitNothingChanges) {
  const fs::path root = fresh("no_commit");
  const fs::path out = root / "out";
  fs::create_directories(out);
  write(out / "model.h5", "old model");
  {
    igaprep::OutputFolder folder(out.string());
    write(fs::path(folder.staging()) / "model.h5", "new model");
  }
  EXPECT_EQ(read(out / "model.h5"), "old model");
  EXPECT_EQ(entries_naming(root, ".igaprep-"), 0);
}

TEST(OutputFolder, ASymlinkedFolderStaysASymlink) {
  const fs::path root = fresh("symlink");
  fs::create_directories(root / "real");
  write(root / "real" / "model.h5", "old model");
  fs::create_directory_symlink("real", root / "link");
  igaprep::OutputFolder folder((root / "link").string());
  write(fs::path(folder.staging()) / "model.h5", "new model");
  folder.commit();
  EXPECT_TRUE(fs::is_symlink(root / "link"));
  EXPECT_EQ(read(root / "real" / "model.h5"), "new model");
}

TEST(OutputFolder, AFolderWithASubfolderGetsItsFilesOneByOne) {
  const fs::path root = fresh("subfolder");
  const fs::path out = root / "out";
  fs::create_directories(out / "mine");
  write(out / "mine" / "data.txt", "kept");
  igaprep::OutputFolder folder(out.string());
  EXPECT_FALSE(folder.atomic());  // a swap could strand the subfolder
  write(fs::path(folder.staging()) / "model.h5", "new model");
  folder.commit();
  EXPECT_EQ(read(out / "model.h5"), "new model");
  EXPECT_EQ(read(out / "mine" / "data.txt"), "kept");
  EXPECT_EQ(entries_naming(out, ".igaprep-"), 0);
}

// One by one, a commit stopped midway (here: a subfolder named as a staged
// file, which no rename can replace) leaves no report about a mix of old
// and new files: the old report goes first, the new one last.
TEST(OutputFolder, OneByOneTheReportGoesLastAndItsOldCopyFirst) {
  const fs::path root = fresh("summaries");
  const fs::path out = root / "out";
  fs::create_directories(out / "model.h5");
  write(out / "model.h5" / "data", "in the way");
  write(out / "report.json", "old report: PASS");
  write(out / "mesh.vtu", "old mesh");
  igaprep::OutputFolder folder(out.string());
  EXPECT_FALSE(folder.atomic());
  write(fs::path(folder.staging()) / "model.h5", "new model");
  write(fs::path(folder.staging()) / "report.json", "new report");
  EXPECT_THROW(folder.commit({"report.json"}), igaprep::Error);
  EXPECT_FALSE(fs::exists(out / "report.json"));
  EXPECT_EQ(read(out / "model.h5" / "data"), "in the way");

  const fs::path clear = root / "clear";
  fs::create_directories(clear / "mine");
  write(clear / "report.json", "old report");
  igaprep::OutputFolder second(clear.string());
  write(fs::path(second.staging()) / "model.h5", "new model");
  write(fs::path(second.staging()) / "report.json", "new report");
  second.commit({"report.json"});
  EXPECT_EQ(read(clear / "report.json"), "new report");
  EXPECT_EQ(read(clear / "model.h5"), "new model");
}

TEST(OutputFolder, StagingFoldersOfProcessesThatEndedAreRemoved) {
  const fs::path root = fresh("stale");
  const fs::path out = root / "out";
  fs::create_directories(out);
  // pid 1 runs; a pid above the kernel's limit never does.
  const fs::path live = root / ".out.igaprep-1-abcdef";
  const fs::path dead = root / ".out.igaprep-99999999-abcdef";
  fs::create_directories(live);
  fs::create_directories(dead);
  write(dead / "model.h5", "a killed run's");
  igaprep::OutputFolder folder(out.string());
  EXPECT_TRUE(fs::exists(live));
  EXPECT_FALSE(fs::exists(dead));
}

}  // namespace
