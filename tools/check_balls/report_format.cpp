#include <nlohmann/json.hpp>

#include "check_balls/check_balls.hpp"
#include "check_balls/violation_log.hpp"

namespace vorocrust::checker {
namespace {

constexpr Condition kConditions[] = {Condition::C1,  Condition::C2,       Condition::C3,        Condition::C4a,
                                     Condition::C4b, Condition::Coverage, Condition::Protection};

}  // namespace

std::string report_text(const BallCheckReport& r) {
  std::string out;
  out += format("strata      %zu corners, %zu creases, %zu patches (sharp angle %g deg)\n", r.corners, r.creases,
                r.patches, r.sharp_angle_degrees);
  out += format("balls       %zu: %zu corner, %zu crease, %zu patch\n",
                r.balls_by_type[0] + r.balls_by_type[1] + r.balls_by_type[2], r.balls_by_type[0], r.balls_by_type[1],
                r.balls_by_type[2]);
  const SampleCounts& s = r.samples;
  out += format("samples     %zu: %zu vertices, %zu edge midpoints, %zu face centroids, %zu on faces, %zu on sharp "
                "edges\n",
                s.total(), s.vertices, s.edge_midpoints, s.face_centroids, s.on_faces, s.on_creases);
  out += format("parameters  L %g, alpha %.6f, tolerance 1e-9 relative\n", r.lipschitz, r.alpha);
  for (Condition c : kConditions) {
    out += format("%-10s  %-40s %zu\n", to_string(c), title(c), r[c].count);
  }
  for (Condition c : kConditions) {
    const ConditionResult& result = r[c];
    if (result.count == 0) continue;
    out += format("\n%s %s: %zu violation%s\n", to_string(c), title(c), result.count, result.count == 1 ? "" : "s");
    for (const Violation& v : result.examples) out += "  " + v.message + "\n";
    if (result.count > result.examples.size()) {
      out += format("  ... %zu more not listed\n", result.count - result.examples.size());
    }
  }
  out += r.ok() ? "\nresult      all ball conditions hold\n"
                : format("\nresult      %zu violations\n", r.violations());
  return out;
}

std::string report_json(const BallCheckReport& r) {
  using nlohmann::json;
  json conditions = json::object();
  for (Condition c : kConditions) {
    json examples = json::array();
    for (const Violation& v : r[c].examples) {
      json e = {{"balls", v.balls}, {"message", v.message}};
      if (v.point) e["point"] = {v.point->x(), v.point->y(), v.point->z()};
      if (!v.stratum.empty()) e["stratum"] = v.stratum;
      examples.push_back(std::move(e));
    }
    conditions[to_string(c)] = {{"title", title(c)}, {"count", r[c].count}, {"examples", std::move(examples)}};
  }
  const SampleCounts& s = r.samples;
  const json doc = {
      {"ok", r.ok()},
      {"violations", r.violations()},
      {"strata", {{"corners", r.corners}, {"creases", r.creases}, {"patches", r.patches}}},
      {"balls",
       {{"corner", r.balls_by_type[0]}, {"crease", r.balls_by_type[1]}, {"patch", r.balls_by_type[2]}}},
      {"samples",
       {{"total", s.total()},
        {"vertices", s.vertices},
        {"edge_midpoints", s.edge_midpoints},
        {"face_centroids", s.face_centroids},
        {"on_faces", s.on_faces},
        {"on_sharp_edges", s.on_creases}}},
      {"parameters", {{"sharp_angle_degrees", r.sharp_angle_degrees}, {"lipschitz", r.lipschitz}, {"alpha", r.alpha}}},
      {"bounding_box_diagonal", r.diagonal},
      {"seconds", r.seconds},
      {"conditions", std::move(conditions)},
  };
  return doc.dump(2);
}

}  // namespace vorocrust::checker
