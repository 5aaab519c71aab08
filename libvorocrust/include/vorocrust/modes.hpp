// vorocrust/modes.hpp — the named choices of a mesh run, each with one to_string/parse pair.
//
// Contract: to_string gives the name every front end uses (`--interior cvt`, interior="cvt", the
// MeshLab and FreeCAD choice lists, report.json); parse_* gives back the value to_string names,
// or nothing for any other text. choice_names<Enum>() lists the names in declaration order.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "vorocrust/api.hpp"

namespace vorocrust {

// How far the pipeline runs: the protecting balls (2.3), the surface seeds and the surface mesh
// (2.4), or the whole Voronoi mesh (2.5 and the cells). Ordered: a later stage has the earlier ones'
// results.
enum class Stage { Balls, Surface, Cells };

// How the volume away from the surface is seeded (paper 2.5, A.5):
// - Random: maximal Poisson-disk sampling with L-Lipschitz radii grown from the surface seeds
//   (dart throwing, then spoke darts), graded from the surface inward;
// - Lattice: a cubic lattice of the local size, giving hex-dominant cells (paper Figure 5f);
// - Cvt: Random, then Lloyd iterations moving interior seeds to their cell centroids while the
//   surface seeds stay where they are (paper Figure 5d).
enum class InteriorMode { Random, Lattice, Cvt };

// What becomes of faces that cut through each other:
// - Resolve: they are cut along their intersection curves, which become creases, and each new
//   piece of space joins a region of the input (resolve_self_intersections.hpp);
// - Refuse: the run stops with the validation's error naming the faces;
// - Keep: meshed as they are, which rarely ends well (the refinement cannot cover a surface
//   that crosses itself).
enum class SelfIntersections { Resolve, Refuse, Keep };

// How the cells meet the surface:
// - Vorocrust: the paper's method: seeds in pairs about the surface, every cell a whole Voronoi
//   cell, convex, the surface made of Voronoi faces that approximate the input;
// - Clipped: seeds inside the volume only (Ebeida and Mitchell's maximal Poisson-disk seeds, or
//   Yan et al.'s CVT), each material's Voronoi cells cut to its region: the boundary and the
//   interfaces are the input exactly, volumes are exact, and the cells the surface cuts are no
//   longer Voronoi cells (not convex in general, their faces on the surface orthogonal to nothing).
enum class Method { Vorocrust, Clipped };

template <class Enum>
struct ChoiceNames;  // the names of an enumeration's values, in declaration order

template <>
struct ChoiceNames<Stage> {
  static constexpr std::array<std::string_view, 3> names = {"balls", "surface", "cells"};
};
template <>
struct ChoiceNames<InteriorMode> {
  static constexpr std::array<std::string_view, 3> names = {"random", "lattice", "cvt"};
};
template <>
struct ChoiceNames<Method> {
  static constexpr std::array<std::string_view, 2> names = {"vorocrust", "clipped"};
};
template <>
struct ChoiceNames<SelfIntersections> {
  static constexpr std::array<std::string_view, 3> names = {"resolve", "refuse", "keep"};
};

template <class Enum>
constexpr std::span<const std::string_view> choice_names() noexcept {
  return ChoiceNames<Enum>::names;
}

template <class Enum>
constexpr std::optional<Enum> parse_choice(std::string_view name) noexcept {
  const auto& names = ChoiceNames<Enum>::names;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == name) return static_cast<Enum>(k);
  }
  return std::nullopt;
}

template <class Enum>
constexpr std::string_view choice_name(Enum value) noexcept {
  const auto k = static_cast<std::size_t>(value);
  return k < ChoiceNames<Enum>::names.size() ? ChoiceNames<Enum>::names[k] : std::string_view("?");
}

// The names are literals, so their data() are NUL-terminated strings (printf's %s takes them).
inline const char* to_string(Stage stage) noexcept { return choice_name(stage).data(); }
inline const char* to_string(InteriorMode mode) noexcept { return choice_name(mode).data(); }
inline const char* to_string(SelfIntersections mode) noexcept { return choice_name(mode).data(); }
inline const char* to_string(Method method) noexcept { return choice_name(method).data(); }
inline std::optional<Stage> parse_stage(std::string_view name) noexcept { return parse_choice<Stage>(name); }
inline std::optional<InteriorMode> parse_interior_mode(std::string_view name) noexcept {
  return parse_choice<InteriorMode>(name);
}
inline std::optional<SelfIntersections> parse_self_intersections(std::string_view name) noexcept {
  return parse_choice<SelfIntersections>(name);
}

}  // namespace vorocrust
