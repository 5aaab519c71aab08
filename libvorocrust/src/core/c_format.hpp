// printf-style text in the "C" locale, whatever the program's: the library's messages and
// summary lines read the same in a host application running with decimal commas (FreeCAD,
// MeshLab and Python under de_DE set LC_NUMERIC), and report.html stays valid.
#pragma once

#include <string>

namespace vorocrust {

std::string c_format(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace vorocrust
