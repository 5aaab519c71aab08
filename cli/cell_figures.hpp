// The line every command that measures cells prints about their faces: how orthogonal they are to
// the seed links (what the cells promise), and checkMesh's figures against the centroids (what
// OpenFOAM will report), so the two are never confused.
#pragma once

#include <cstdio>

#include "vorocrust/cell_quality.hpp"

namespace vorocrust::cli {

void print_face_figures(const CellQuality& q, std::FILE* to);

}  // namespace vorocrust::cli
