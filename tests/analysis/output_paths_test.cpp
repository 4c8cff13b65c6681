// The outputs of one command checked together before it runs: folders and files that can be
// made, and no output that is one of the inputs.

#include "dynpos/analysis/output_paths.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "../io/io_test_util.hpp"
#include "dynpos/analysis/option_spelling.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using testing::input_error;

TEST(OutputPaths, AValueNamesItselfAndTheFilesOfItsAssignments) {
  EXPECT_EQ(paths_in("log.csv"), (std::vector<std::string>{"log.csv"}));
  EXPECT_EQ(paths_in("heading=HDG@nav.csv"),
            (std::vector<std::string>{"heading=HDG@nav.csv", "nav.csv", "heading"}));
  EXPECT_EQ(paths_in("nav.csv=0.2"), (std::vector<std::string>{"nav.csv=0.2", "nav.csv"}));
}

TEST(OutputPaths, NewFilesAndFoldersInAWritableFolderPass) {
  const TempDir dir;
  CommandPaths paths;
  paths.output_files = {{"json", (dir / "r.json").string()}, {"json", "-"}, {"plot", ""}};
  paths.output_folders = {{"out", (dir / "figures").string()}};
  paths.inputs = {{"log", dir.write("log.csv", "time\n0\n").string()}};
  EXPECT_NO_THROW(check_command_paths(paths));
}

TEST(OutputPaths, AnOutputThatIsAnInputNamesBoth) {
  const TempDir dir;
  const std::string log = dir.write("log.csv", "time\n0\n").string();
  CommandPaths paths;
  paths.output_files = {{"json", log}};
  paths.inputs = {{"--map", (dir / "map.toml").string()}, {"log", log}};
  const core::InputError e = input_error([&] { check_command_paths(paths); });
  EXPECT_EQ(e.option(), "json");
  EXPECT_EQ(e.problem(),
            "'" + log + "' is the input '" + log + "' (log): writing it would destroy the input");
  EXPECT_EQ(e.hint(), "write the output to another file");
  // The same file by another name: the device and inode decide.
  paths.output_files = {{"plot", (dir / "." / "log.csv").string()}};
  EXPECT_EQ(input_error([&] { check_command_paths(paths); }).option(), "plot");
}

TEST(OutputPaths, AFileInAnOutputFolderNotMadeYetIsNotChecked) {
  const TempDir dir;
  const std::string folder = (dir / "new").string();
  CommandPaths paths;
  paths.output_folders = {{"out", folder}};
  paths.output_files = {{"json", folder + "/r.json"}};
  EXPECT_NO_THROW(check_command_paths(paths));
  // Without the folder among the outputs, the missing folder is the file's error.
  paths.output_folders.clear();
  const core::InputError e = input_error([&] { check_command_paths(paths); });
  EXPECT_EQ(e.option(), "json");
  EXPECT_EQ(e.problem(), "folder '" + folder + "' does not exist");
}

TEST(OutputPaths, AnOutputFolderThatIsAFileIsRefusedFirst) {
  const TempDir dir;
  const std::string file = dir.write("plots", "x").string();
  CommandPaths paths;
  paths.output_files = {{"json", file}};
  paths.inputs = {{"log", file}};
  paths.output_folders = {{"plots", file}};
  const core::InputError e = input_error([&] { check_command_paths(paths); });
  EXPECT_EQ(cli_message(e), "(--plots): '" + file +
                                "' exists and is not a folder; name a folder (it is created if "
                                "needed)");
}

}  // namespace
}  // namespace dynpos::analysis
