// vorocrust/vorocrust.hpp — everything a program linking libvorocrust needs.
#pragma once

#include "vorocrust/atomic_file.hpp"
#include "vorocrust/cells.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/mesh_info.hpp"
#include "vorocrust/mesher.hpp"
#include "vorocrust/progress.hpp"
#include "vorocrust/quality.hpp"
#include "vorocrust/quality_svg.hpp"
#include "vorocrust/read_mesh.hpp"
#include "vorocrust/report.hpp"
#include "vorocrust/surface_mesh.hpp"
#include "vorocrust/threads.hpp"
#include "vorocrust/validate.hpp"
#include "vorocrust/version.hpp"
#include "vorocrust/write_mesh.hpp"
