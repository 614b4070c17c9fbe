#include "server/relay/static_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace mc::relay {
namespace {

class StaticFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    base_ = fs::temp_directory_path() / ("mc-static-" + std::to_string(::getpid()));
    fs::remove_all(base_);
    fs::create_directories(base_ / "web" / "src");
    std::ofstream(base_ / "web" / "index.html") << "<html>";
    std::ofstream(base_ / "web" / "src" / "main.js") << "x";
    std::ofstream(base_ / "secret.txt") << "secret";
    fs::create_directories(base_ / "web-evil");
    std::ofstream(base_ / "web-evil" / "x.txt") << "evil";
    fs::create_symlink(base_ / "secret.txt", base_ / "web" / "link.txt");
  }
  void TearDown() override { fs::remove_all(base_); }
  fs::path base_;
};

TEST_F(StaticFilesTest, NamesThePageFilesThatAreMissing) {
  StaticFiles files((base_ / "web").string());
  // No three.js: the page would be blank, so the server must say so.
  EXPECT_EQ(files.missing_page_files(), std::vector<std::string>{"node_modules/three/build/three.module.js"});
  fs::create_directories(base_ / "web" / "node_modules" / "three" / "build");
  std::ofstream(base_ / "web" / "node_modules" / "three" / "build" / "three.module.js") << "export {}";
  EXPECT_TRUE(files.missing_page_files().empty());
  fs::remove(base_ / "web" / "index.html");
  EXPECT_EQ(files.missing_page_files(), std::vector<std::string>{"index.html"});
}

TEST_F(StaticFilesTest, ServesFilesInsideTheRoot) {
  StaticFiles files((base_ / "web").string());
  auto index = files.resolve("/");
  ASSERT_TRUE(index);
  EXPECT_EQ(fs::path(*index).filename(), "index.html");
  auto js = files.resolve("/src/main.js?v=3");
  ASSERT_TRUE(js);
  EXPECT_EQ(fs::path(*js).filename(), "main.js");
  EXPECT_TRUE(files.resolve("/src/%6Dain.js"));  // percent-encoded 'm'
}

TEST_F(StaticFilesTest, RefusesEveryEscape) {
  StaticFiles files((base_ / "web").string());
  for (const char* target :
       {"/../secret.txt", "/src/../../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E%2Fsecret.txt",
        "/..%2fsecret.txt", "/src/..\\..\\secret.txt", "/link.txt", "/../web-evil/x.txt",
        "//etc/passwd", "/%00index.html", "/index.html%", "/index.html%zz", "", "index.html",
        "/missing.js", "/src"}) {
    EXPECT_FALSE(files.resolve(target)) << target;
  }
}

TEST(MimeType, KnowsTheWebTypes) {
  EXPECT_EQ(mime_type("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(mime_type("three.module.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(mime_type("noext"), "application/octet-stream");
}

}  // namespace
}  // namespace mc::relay
