// `vorocrust check-balls`: reads the surface and a balls.csv and reports every ball condition the
// balls break, through the independent checker in tools/check_balls.
#include <cstdio>
#include <filesystem>

#include "check_balls/check_balls.hpp"
#include "check_balls_command.hpp"
#include "domain_args.hpp"
#include "exit_codes.hpp"
#include "vorocrust/error.hpp"

namespace vorocrust::cli {

int run_check_balls(const CheckBallsArgs& args) {
  if (args.files.size() < 2) {
    throw Error(Error::Kind::Usage, "check-balls needs the input meshes and then the balls CSV");
  }
  checker::BallCheckOptions options;
  MeshOptions mesher;  // the same defaults as the run that made the balls
  mesher.smooth = args.smooth;
  mesher.sharp_angle_degrees = args.sharp_angle_degrees;
  args.domain.apply(mesher);
  options.sharp_angle_degrees = mesher.sharp_angle();
  options.lipschitz = args.lipschitz;
  options.face_samples = args.face_samples;
  options.crease_samples = args.crease_samples;
  options.seed = args.seed;
  options.check();  // before reading anything, so a bad option fails fast

  // The balls cover the surface the run started from: the input in its box, cut along its
  // self-intersections (a smoothed_surface.ply is that already, and stays as it is).
  const std::vector<std::filesystem::path> inputs(args.files.begin(), args.files.end() - 1);
  const SurfaceMesh mesh = read_domain(inputs, mesher);
  const std::vector<checker::CheckedBall> balls = checker::read_balls_csv(args.files.back());

  const checker::BallCheckReport report = checker::check_balls(mesh, balls, options);
  if (args.json) {
    std::printf("%s\n", checker::report_json(report).c_str());
  } else {
    std::printf("input       ");
    for (std::size_t i = 0; i + 1 < args.files.size(); ++i) std::printf("%s%s", i ? ", " : "", args.files[i].c_str());
    std::printf(" (%zu faces)\nballs file  %s\n%s", mesh.num_faces(), args.files.back().c_str(),
                checker::report_text(report).c_str());
  }
  if (!report.ok()) {
    std::fprintf(stderr, "vorocrust: ball conditions violated: %zu violations\n", report.violations());
    return kConditionsViolated;
  }
  return kOk;
}

}  // namespace vorocrust::cli
