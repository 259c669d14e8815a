// The MIM table cache: the folder (core/cache_dir.hpp: --cache-dir or model
// option, $RAILSIM_CACHE_DIR, $XDG_CACHE_HOME/railsim, ...), the file named by
// the parameter hash, and load-or-build under an exclusive lock on
// "<file>.lock" (core/file_lock.hpp), so concurrent processes (MPI ranks, two
// users of one cache) and threads build a table once; see mim_table.hpp.
#include <cstdio>
#include <filesystem>
#include <string>

#include "contact/mim_table/mim_table.hpp"
#include "core/cache_dir.hpp"
#include "core/errors.hpp"
#include "core/file_lock.hpp"

namespace railsim::contact {

std::string mim_table_cache_dir(const std::string& configured) { return cache_dir(configured, "mim_table"); }

std::string mim_table_cache_path(const MimTableSpec& spec, const std::string& configured_cache_dir) {
  char name[64];
  std::snprintf(name, sizeof name, "mim_table_%016llx.bin", static_cast<unsigned long long>(spec.hash()));
  return mim_table_cache_dir(configured_cache_dir) + "/" + name;
}

std::shared_ptr<const MimTable> load_or_build_mim_table(const MimTableSpec& spec, const std::string& cache_dir,
                                                        const std::function<void(const std::string&)>& log) {
  spec.check();
  const std::string path = mim_table_cache_path(spec, cache_dir);
  const FileLock lock(path + ".lock");
  if (std::filesystem::exists(path)) {
    try {
      return MimTable::load(path, spec);
    } catch (const InputError& e) {
      if (log) log(std::string(e.what()) + "; rebuilding it");
    }
  } else if (log) {
    log("mim_table: building " + path + " (" + std::to_string(spec.size()) + " exact solves, grid " +
        std::to_string(spec.grid) + ")");
  }
  MimTableBuildOptions o;
  std::size_t last = 0;
  o.progress = [&](std::size_t done, std::size_t total) {
    if (log && (done * 20 / total != last * 20 / total || done == total))
      log("mim_table: " + std::to_string(done) + " / " + std::to_string(total) + " nodes");
    last = done;
  };
  const std::string partial = path + ".partial";
  auto t = MimTable::build(spec, partial, o);
  t->save(path);
  std::error_code ec;
  std::filesystem::remove(partial, ec);
  return t;
}

}  // namespace railsim::contact
