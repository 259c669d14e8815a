// FNV-1a 64 against the published test vectors of the FNV reference
// (Fowler/Noll/Vo; draft-eastlake-fnv): "" -> cbf29ce484222325,
// "a" -> af63dc4c8601ec8c, "foobar" -> 85944171f73967e8.
#include <catch2/catch.hpp>

#include <string>

#include "core/content_hash.hpp"

using railsim::ContentHash;
using railsim::fnv1a;

TEST_CASE("FNV-1a 64 matches the reference test vectors", "[core][hash]") {
  CHECK(fnv1a("", 0) == 0xcbf29ce484222325ull);
  CHECK(fnv1a("a", 1) == 0xaf63dc4c8601ec8cull);
  CHECK(fnv1a("foobar", 6) == 0x85944171f73967e8ull);
  CHECK(ContentHash().text("foobar").value() == 0x85944171f73967e8ull);
}

TEST_CASE("FNV-1a: incremental equals one shot, order and bytes matter", "[core][hash]") {
  const std::string s = "railsim contact table";
  CHECK(ContentHash().text(s.substr(0, 7)).text(s.substr(7)).value() == fnv1a(s.data(), s.size()));
  CHECK(fnv1a(s.data() + 7, s.size() - 7, fnv1a(s.data(), 7)) == fnv1a(s.data(), s.size()));
  CHECK(ContentHash().value(1.0).value(2.0).value() != ContentHash().value(2.0).value(1.0).value());
  CHECK(ContentHash().value(0.0).value() != ContentHash().value(-0.0).value());
  const double d = 0.1;
  CHECK(ContentHash().value(d).value() == fnv1a(&d, sizeof d));
}
