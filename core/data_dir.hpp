// Where railsim finds the data it ships (profiles, the chart script, vehicles,
// tracks, scenarios): the data folder, laid out as
//   <data>/profiles/  <data>/plots/render_chart.py  <data>/vehicles/
//   <data>/tracks/    <data>/scenarios/             <data>/railsim-data.txt
//
// Resolution: $RAILSIM_DATA_DIR when set (not empty); else the folder
// share/railsim found relative to the binary that holds this code (the
// program, a test, the Python module): its own folder and up to four parents
// are tried, so <prefix>/bin/railsim and
// <prefix>/lib/python3/dist-packages/railsim/_railsim*.so both find
// <prefix>/share/railsim, and the build tree finds <build>/share/railsim, which
// the build fills with copies of the sources' data. A folder counts only when
// it holds the marker file railsim-data.txt. No source path is compiled in.
#pragma once

#include <string>

namespace railsim {

// The data folder; throws InputError saying what was tried when none is found.
std::string data_dir();

// The data folder or an empty string (no error).
std::string find_data_dir();

// <data folder>/<relative>.
std::string data_path(const std::string& relative);

// The file of the binary (program or shared object) holding this code.
std::string binary_path();

}  // namespace railsim
