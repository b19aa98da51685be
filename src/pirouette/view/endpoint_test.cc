#include "pirouette/view/endpoint.h"

#include <gtest/gtest.h>

#include "pirouette/core/input_error.h"

namespace pirouette::view {
namespace {

TEST(EndpointTest, APortAloneListensOnLoopback) {
  const Endpoint e = ParseEndpoint("8765");
  EXPECT_EQ(e.host, "127.0.0.1");
  EXPECT_EQ(e.port, 8765);
  EXPECT_EQ(HttpUrl(e), "http://127.0.0.1:8765/");
}

TEST(EndpointTest, TakesAHostAndABracketedIpv6) {
  EXPECT_EQ(ParseEndpoint("0.0.0.0:80").host, "0.0.0.0");
  const Endpoint v6 = ParseEndpoint("[::1]:9000");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.port, 9000);
  EXPECT_EQ(HttpUrl(v6), "http://[::1]:9000/");
}

TEST(EndpointTest, RefusesWhatIsNoEndpointNamingTheOption) {
  for (const char* bad : {"", "http", "99999", ":80", "host:", "::1:80", "80x", "-1"}) {
    try {
      ParseEndpoint(bad, "--view");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const core::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--view"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace pirouette::view
