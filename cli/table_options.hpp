// The command line's options made from the library's option table (vorocrust/options.hpp): one
// flag per option, spelled `--sharp-angle`, whose help is the table's help with the default and
// the range, and whose value the library parses and checks.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "vorocrust/options.hpp"

namespace CLI {
class App;
}

namespace vorocrust::cli {

class TableOptions {
 public:
  // A flag on `command` for every option of the table the CLI offers, or for those named.
  void add(CLI::App& command, const std::vector<std::string_view>& names = {});
  // Sets every option given on the command line; throws Error(Usage) naming the option.
  void apply(MeshOptions& options) const;
  bool given(std::string_view name) const {
    const auto it = values_.find(std::string(name));
    return it != values_.end() && !it->second.empty();
  }

 private:
  std::map<std::string, std::vector<std::string>> values_;
};

}  // namespace vorocrust::cli
