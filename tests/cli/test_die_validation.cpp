// SPDX-License-Identifier: MIT
// Die-geometry input errors: exit code 2 with file:line, key and hint; nothing written.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& text) { return "'" + text + "'"; }

std::string read_text(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

struct BadDie {
  std::string file;
  int line;
  std::string key;
  std::string hint;
};

const BadDie bad_dies[] = {
    {"die-angle-90.toml", 4, "geometry.die_angle", "0 < value < 90"},
    {"die-no-reduction.toml", 5, "geometry.exit_half_height", "< geometry.entry_half_height"},
    {"die-arc-too-small.toml", 4, "geometry.die_radius", "≥ entry_half_height − exit_half_height = 5"},
    {"die-profile-widens.toml", 4, "geometry.die_profile", "y increases at point 3"},
    {"die-profile-wrong-end.toml", 4, "geometry.die_profile", "end the profile at y = "},
    {"die-land-unfit.toml", 4, "geometry.land_length", "not a multiple of mesh.size"},
};

TEST(DieValidation, BadDieExitsTwoNamingFileLineAndKey) {
  const fs::path scratch = fs::temp_directory_path() / ("formflow-die-" + std::to_string(getpid()));
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  for (const BadDie& bad : bad_dies) {
    SCOPED_TRACE(bad.file);
    const std::string path =
        (fs::path(FORMFLOW_SOURCE_DIR) / "tests" / "data" / "cases" / bad.file).string();
    const fs::path output = scratch / "results", err = scratch / "stderr.txt";
    const std::string command = quoted(FORMFLOW_BINARY) + " run " + quoted(path) + " -o " +
                                quoted(output.string()) + " > /dev/null 2> " + quoted(err.string());
    const int status = std::system(command.c_str());
    const std::string text = read_text(err);
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << text;
    EXPECT_NE(text.find(path + ":" + std::to_string(bad.line) + ": " + bad.key + ": "),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(bad.hint), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(output));
  }
  fs::remove_all(scratch);
}

}  // namespace

namespace {

TEST(DieValidation, GoodPolylineAndArcPassCheck) {
  const std::string binary =
      "'" + std::string(FORMFLOW_BINARY) + "' check '" + FORMFLOW_SOURCE_DIR +
      "/cases/paper-q2-2x2-mesh2.toml'";
  const std::string polyline = binary +
                               " --set geometry.die=polyline"
                               " --set 'geometry.die_profile=[[0, 10], [4, 7.5], [9.5, 5]]'"
                               " --set geometry.land_length=2 > /dev/null 2>&1";
  int status = std::system(polyline.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0);
  const std::string arc = binary +
                          " --set geometry.die=arc --set geometry.die_radius=5"
                          " --set geometry.symmetry=axisymmetric --set process.type=drawing"
                          " > /dev/null 2>&1";
  status = std::system(arc.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0);
  // A profile entry that is not an [x, y] pair is a type error, exit 2.
  const std::string bad = binary + " --set 'geometry.die_profile=[[0, 10, 3]]' > /dev/null 2>&1";
  status = std::system(bad.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
}

}  // namespace
