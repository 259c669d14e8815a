// The one cache folder of railsim (contact-geometry tables, MIM tables, ...).
//
// Resolution order: the folder configured by the caller (a --cache-dir option,
// a model option) when not empty; else $RAILSIM_CACHE_DIR; else
// $XDG_CACHE_HOME/railsim (XDG Base Directory Specification 0.8); else
// $HOME/.cache/railsim; else ./.railsim_cache. Empty variables count as unset.
#pragma once

#include <string>

namespace railsim {

// The folder (not created).
std::string resolve_cache_dir(const std::string& configured = "");

// The folder, created when missing; throws InputError naming `what` (e.g.
// "mim_table") and the folder when it cannot be created.
std::string cache_dir(const std::string& configured, const std::string& what);

}  // namespace railsim
