// Internal: the regions' names as words for file names and OpenFOAM dictionaries.
#pragma once

#include <map>
#include <string>

#include "vorocrust/cells.hpp"

namespace vorocrust::io {

// region_name(mesh, label) with every character outside [A-Za-z0-9_] made '_' (a leading digit
// gets a '_' before it); where two names give one word, the later label's word ends in
// "_<label>", so words stay apart.
class RegionWords {
 public:
  explicit RegionWords(const VoronoiMesh& mesh);
  const std::string& operator()(std::int32_t label) const;

 private:
  std::map<std::int32_t, std::string> words_;
};

}  // namespace vorocrust::io
