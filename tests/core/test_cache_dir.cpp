// The one cache folder: configured folder, else $RAILSIM_CACHE_DIR, else
// $XDG_CACHE_HOME/railsim, else $HOME/.cache/railsim; and every cache uses it
// (the contact-geometry table cache writes into $RAILSIM_CACHE_DIR).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/profile.hpp"
#include "contact/geometry/wheel_rail_geometry.hpp"
#include "contact/mim_table/mim_table.hpp"
#include "core/cache_dir.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

TEST_CASE("cache folder resolution order", "[core][cache_dir]") {
  setenv("RAILSIM_CACHE_DIR", "/tmp/rc", 1);
  setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  setenv("HOME", "/tmp/home", 1);
  CHECK(railsim::resolve_cache_dir("/tmp/opt") == "/tmp/opt");
  CHECK(railsim::resolve_cache_dir() == "/tmp/rc");
  setenv("RAILSIM_CACHE_DIR", "", 1);  // empty counts as unset
  CHECK(railsim::resolve_cache_dir() == "/tmp/xdg/railsim");
  unsetenv("RAILSIM_CACHE_DIR");
  unsetenv("XDG_CACHE_HOME");
  CHECK(railsim::resolve_cache_dir() == "/tmp/home/.cache/railsim");
  unsetenv("HOME");
  CHECK(railsim::resolve_cache_dir() == ".railsim_cache");
  // Both table caches resolve through it.
  setenv("RAILSIM_CACHE_DIR", "/tmp/rc2", 1);
  CHECK(railsim::contact::ContactTable::default_cache_dir() == "/tmp/rc2");
}

TEST_CASE("cache_dir creates the folder or names it in the error", "[core][cache_dir]") {
  const std::string dir = railsim::test::temp_dir("cache_dir");
  CHECK(railsim::cache_dir(dir + "/a/b", "test") == dir + "/a/b");
  CHECK(fs::is_directory(dir + "/a/b"));
  std::FILE* f = std::fopen((dir + "/file").c_str(), "w");
  std::fclose(f);
  try {
    railsim::cache_dir(dir + "/file/sub", "mim_table");
    FAIL("no error");
  } catch (const railsim::InputError& e) {
    CHECK(std::string(e.what()).find("mim_table: cannot create cache folder '" + dir + "/file/sub'") == 0);
  }
}

TEST_CASE("the contact-geometry cache honours RAILSIM_CACHE_DIR", "[core][cache_dir][geometry]") {
  const std::string dir = railsim::test::temp_dir("cache_env");
  setenv("RAILSIM_CACHE_DIR", dir.c_str(), 1);
  using namespace railsim::contact;
  const Profile w = read_profile("S1002", ProfileKind::wheel), r = read_profile("UIC60", ProfileKind::rail);
  TrackSetup ts;
  ts.inclination = std::atan(1.0 / 40.0);
  const WheelRailGeometry g(w, r, ts);
  const TableGrid grid{-0.004, 0.004, 1e-3};
  bool cached = true;
  const ContactTable t1 = ContactTable::cached(g, w, r, grid, "", &cached);
  CHECK_FALSE(cached);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir))
    files += e.path().filename().string().rfind("contact_table_", 0) == 0 ? 1 : 0;
  CHECK(files == 1);
  const ContactTable t2 = ContactTable::cached(g, w, r, grid, "", &cached);
  CHECK(cached);
  REQUIRE(t1.rows() == t2.rows());
  for (std::size_t i = 0; i < t1.rows(); ++i) CHECK(t1.value(i, 4) == t2.value(i, 4));
  CHECK(railsim::contact::mim_table_cache_dir("") == dir);
}
