// Motion folders: every *.toml file is read; a bad file, an id outside the folder's range or an id
// taken twice stops the load with the file's name; the shipped folder loads.
#include "motions/motion_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

// a fresh folder of this test process
class MotionFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("cerebellum_motions_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  void write(const std::string& name, int id) {
    std::ofstream(folder_ / name) << "id = " << id << "\nname = \"m" << id
                                  << "\"\n[[step]]\nmode = 21\ngait_id = 0\nduration = 500\n";
  }
  std::string load_error(int first, int last) {
    MotionLibrary library;
    try {
      load_motion_folder(folder_.string(), first, last, library);
    } catch (const MotionFileError& e) {
      return e.what();
    }
    return "";
  }

  fs::path folder_;
};

TEST_F(MotionFolder, ReadsEveryTomlFileAndNothingElse) {
  write("a.toml", 81);
  write("b.toml", 95);
  std::ofstream(folder_ / "notes.txt") << "not a motion";
  MotionLibrary library;
  load_motion_folder(folder_.string(), kFirstUserMotionId, kLastUserMotionId, library);
  EXPECT_EQ(library.id_list(), "81 95");
  EXPECT_EQ(library.find(95)->origin, (folder_ / "b.toml").string());
}

TEST_F(MotionFolder, AnIdOutsideTheFoldersRangeNamesTheFile) {
  write("low.toml", 12);
  EXPECT_NE(
      load_error(kFirstUserMotionId, kLastUserMotionId).find("low.toml: id 12 is outside this folder's ids [80, 100]"),
      std::string::npos);
}

TEST_F(MotionFolder, AnIdTakenTwiceNamesBothFiles) {
  write("a.toml", 90);
  write("b.toml", 90);
  const std::string error = load_error(kFirstUserMotionId, kLastUserMotionId);
  EXPECT_NE(error.find("b.toml: id 90 is taken by "), std::string::npos) << error;
  EXPECT_NE(error.find("a.toml"), std::string::npos) << error;
}

TEST_F(MotionFolder, AMalformedFileNamesTheFileAndTheProblem) {
  std::ofstream(folder_ / "bad.toml") << "id = 85\nname = \"x\"\n[[step]]\nmode = 21\n";
  const std::string error = load_error(kFirstUserMotionId, kLastUserMotionId);
  EXPECT_NE(error.find("bad.toml: step 1: gait_id is missing"), std::string::npos) << error;
}

TEST_F(MotionFolder, AFolderThatIsNotThereIsNamed) {
  const std::string missing = (folder_ / "nowhere").string();
  MotionLibrary library;
  try {
    load_motion_folder(missing, 1, 79, library);
    FAIL();
  } catch (const MotionFileError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": is not a folder of motion files");
  }
}

TEST_F(MotionFolder, UserGaitFilesAreFoundNextToTheMotionFile) {
  std::ofstream(folder_ / "walk.toml") << "id = 84\nname = \"w\"\nuser_gait = { definition = \"gaits/d.toml\", "
                                          "parameters = \"/abs/p.toml\" }\n[[step]]\nmode = 11\ngait_id = 110\n"
                                          "duration = 500\n";
  MotionLibrary library;
  load_motion_folder(folder_.string(), kFirstUserMotionId, kLastUserMotionId, library);
  EXPECT_EQ(library.find(84)->user_gait_definition, (folder_ / "gaits/d.toml").string());
  EXPECT_EQ(library.find(84)->user_gait_parameters, "/abs/p.toml");
}

TEST(ShippedMotions, LoadWithTheReferencesMotionIds) {
  const MotionLibrary library = load_motion_library({CEREBELLUM_SOURCE_DIR "/config/motions", ""});
  for (int id : {1, 2, 3, 4, 5, 6, 11, 12, 34}) EXPECT_NE(library.find(id), nullptr) << id;
}

}  // namespace
}  // namespace cerebellum
