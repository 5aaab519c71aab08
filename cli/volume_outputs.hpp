// The lines that tell where each volume format went and what opens it.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace vorocrust::cli {

void print_volume_outputs(const std::filesystem::path& folder, const std::vector<std::string>& formats,
                          std::FILE* to = stderr);

}  // namespace vorocrust::cli
