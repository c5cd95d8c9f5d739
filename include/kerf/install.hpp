#pragma once
// Where an installed kerf keeps its bundled data. `cmake --install` and `pip install .` put the programs in
// PREFIX/bin and the data in PREFIX/share/kerf/data; the Python module lands in
// PREFIX/lib/pythonX.Y/site-packages (or dist-packages). A binary finds the data from its own location, so an
// installed tree can move; a binary in the build tree finds none and uses the source tree's data/.
//
//   if (auto dir = kerf::installed_data_directory(); !dir.empty()) ...  // PREFIX/share/kerf/data
#include <filesystem>

namespace kerf {

/// PREFIX/share/kerf/data of the installed kerf this code runs from, found from the location of the program or
/// the Python module holding it (it must contain materials/); empty when this code is not installed so.
std::filesystem::path installed_data_directory();

}  // namespace kerf
