#include "check_balls/ball_sites.hpp"

#include <limits>
#include <optional>

namespace vorocrust::checker {
namespace {

BallSite site_of(const Strata& strata, StratumType type, const Nearest& nearest) {
  BallSite site{{type, kNone}, {}};
  if (nearest.elements.empty()) return site;
  switch (type) {
    case StratumType::Corner:
      site.stratum.index = nearest.elements.front();
      break;
    case StratumType::Crease:
      site.stratum.index = strata.edge_crease[nearest.elements.front()];
      for (Index e : nearest.elements) {
        if (strata.edge_crease[e] == site.stratum.index) site.directions.push_back(strata.edge_direction[e]);
      }
      break;
    case StratumType::Patch:
      site.stratum.index = strata.face_patch[nearest.elements.front()];
      for (Index f : nearest.elements) {
        if (strata.face_patch[f] == site.stratum.index && !strata.face_normal[f].isZero()) {
          site.directions.push_back(strata.face_normal[f]);
        }
      }
      break;
  }
  return site;
}

std::string misplacement(const Strata& strata, const CheckedBall& ball, std::optional<StratumType> on,
                         const Nearest& corner, const Nearest& edge, const Nearest& face) {
  if (on == StratumType::Corner) {
    return format("%s ball is centred on corner %u", to_string(ball.type), corner.elements.front());
  }
  if (on == StratumType::Crease) {
    return format("%s ball is centred on crease %u", to_string(ball.type), strata.edge_crease[edge.elements.front()]);
  }
  switch (ball.type) {
    case StratumType::Corner:
      if (corner.elements.empty()) return "corner ball, but the surface has no corners";
      return format("corner ball is not on a corner: nearest corner %u at distance %.6g", corner.elements.front(),
                    corner.distance);
    case StratumType::Crease:
      if (edge.elements.empty()) return "crease ball, but the surface has no creases";
      return format("crease ball is not on a crease: nearest sharp edge (crease %u) at distance %.6g",
                    strata.edge_crease[edge.elements.front()], edge.distance);
    case StratumType::Patch:
      break;
  }
  return format("patch ball is not on the surface: nearest face at distance %.6g", face.distance);
}

}  // namespace

std::vector<BallSite> locate_balls(const SurfaceMesh& /*mesh*/, const Strata& strata, const SurfaceLocator& locator,
                                   const std::vector<CheckedBall>& balls, double tolerance, ViolationLog& log) {
  std::vector<BallSite> sites;
  sites.reserve(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const CheckedBall& ball = balls[i];
    const Nearest corner = locator.nearest_corner(ball.centre, tolerance);
    const Nearest edge = locator.nearest_sharp_edge(ball.centre, tolerance);
    const Nearest face = locator.nearest_face(ball.centre, tolerance);
    std::optional<StratumType> on;
    if (corner.distance <= tolerance) {
      on = StratumType::Corner;
    } else if (edge.distance <= tolerance) {
      on = StratumType::Crease;
    } else if (face.distance <= tolerance) {
      on = StratumType::Patch;
    }
    const Nearest& own = ball.type == StratumType::Corner ? corner : ball.type == StratumType::Crease ? edge : face;
    sites.push_back(site_of(strata, ball.type, own));
    if (on != ball.type) {
      log.add(Condition::Protection, i, [&] {
        Violation v;
        v.balls = {i};
        v.point = ball.centre;
        v.stratum = describe(sites.back().stratum);
        v.message = describe_ball(balls, i) + ": " + misplacement(strata, ball, on, corner, edge, face);
        return v;
      });
    }
  }
  return sites;
}

void check_corner_balls(const SurfaceMesh& mesh, const Strata& strata, const std::vector<CheckedBall>& balls,
                        double tolerance, ViolationLog& log) {
  std::vector<Point> centres;
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (balls[i].type == StratumType::Corner) centres.push_back(balls[i].centre), ids.push_back(i);
  }
  const SphereIndex index(centres, std::vector<double>(centres.size(), 0.0));
  for (Index k = 0; k < strata.num_corners(); ++k) {
    const Point& x = mesh.vertices[strata.corner_vertex[k]];
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = 0;
    index.for_each_group_nearest(x, [&](Index j) {
      const double d = (x - centres[j]).norm();
      if (d < best) best = d, nearest = ids[j];
    });
    if (best <= tolerance) continue;
    log.add(Condition::Protection, std::nullopt, [&] {
      Violation v;
      v.point = x;
      v.stratum = describe(StratumRef{StratumType::Corner, k});
      v.message = format("corner %u at %s has no corner ball", k, describe(x).c_str());
      if (!centres.empty()) {
        v.balls = {nearest};
        v.message += format(" (nearest: %s at distance %.6g)", describe_ball(balls, nearest).c_str(), best);
      }
      return v;
    });
  }
}

}  // namespace vorocrust::checker
