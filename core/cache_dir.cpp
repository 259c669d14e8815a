// Cache folder resolution; see cache_dir.hpp.
#include "core/cache_dir.hpp"

#include <cstdlib>
#include <filesystem>

#include "core/errors.hpp"

namespace railsim {

namespace {
const char* env(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? v : nullptr;
}
}  // namespace

std::string resolve_cache_dir(const std::string& configured) {
  if (!configured.empty()) return configured;
  if (const char* e = env("RAILSIM_CACHE_DIR")) return e;
  if (const char* x = env("XDG_CACHE_HOME")) return std::string(x) + "/railsim";
  if (const char* h = env("HOME")) return std::string(h) + "/.cache/railsim";
  return ".railsim_cache";
}

std::string cache_dir(const std::string& configured, const std::string& what) {
  const std::string dir = resolve_cache_dir(configured);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(what + ": cannot create cache folder '" + dir + "': " + ec.message());
  return dir;
}

}  // namespace railsim
