#include "pirouette/view/web_assets.h"

#include <gtest/gtest.h>

namespace pirouette::view {
namespace {

TEST(WebAssetsTest, TheRootIsTheIndexPage) {
  const std::optional<WebAsset> index = FindWebAsset("/");
  ASSERT_TRUE(index.has_value());
  EXPECT_EQ(index->name, "index.html");
  EXPECT_EQ(index->content_type, "text/html; charset=utf-8");
  const std::string_view text(reinterpret_cast<const char*>(index->bytes.data()),
                              index->bytes.size());
  EXPECT_NE(text.find("<html"), std::string_view::npos);
  EXPECT_EQ(FindWebAsset("/?x=1")->name, "index.html");
  EXPECT_EQ(FindWebAsset("/app.js")->content_type, "text/javascript; charset=utf-8");
}

TEST(WebAssetsTest, ServesNothingButItsOwnFiles) {
  for (const char* path : {"/../etc/passwd", "/..%2fetc/passwd", "/web/index.html", "//app.js",
                           "/index.html/", "", "index.html", "/nothing.js"}) {
    EXPECT_FALSE(FindWebAsset(path).has_value()) << path;
  }
}

}  // namespace
}  // namespace pirouette::view
