#include "export/region_words.hpp"

#include <cctype>
#include <set>

namespace vorocrust::io {

namespace {

std::string word_of(const std::string& name) {
  std::string word;
  for (unsigned char c : name) word += std::isalnum(c) || c == '_' ? static_cast<char>(c) : '_';
  if (word.empty() || std::isdigit(static_cast<unsigned char>(word.front()))) word.insert(word.begin(), '_');
  return word;
}

}  // namespace

RegionWords::RegionWords(const VoronoiMesh& mesh) {
  std::set<std::int32_t> labels{kOutsideRegion};
  for (std::size_t r = 0; r < mesh.region_names.size(); ++r) labels.insert(static_cast<std::int32_t>(r));
  for (const VoronoiCell& c : mesh.cells) labels.insert(c.region);
  for (const VoronoiFace& f : mesh.faces) labels.insert({f.regions.back, f.regions.front});
  std::set<std::string> taken;
  for (std::int32_t label : labels) {
    std::string word = word_of(region_name(mesh, label));
    if (!taken.insert(word).second) {
      word.append("_").append(std::to_string(label));  // not "_" + ...: GCC 12 warns falsely (-Wrestrict)
      taken.insert(word);
    }
    words_[label] = word;
  }
}

const std::string& RegionWords::operator()(std::int32_t label) const { return words_.at(label); }

}  // namespace vorocrust::io
