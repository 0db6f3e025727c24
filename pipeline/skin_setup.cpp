#include "skinfem/pipeline/skin_setup.hpp"

#include "skinfem/mesh/build.hpp"
#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/clock.hpp"
#include "skinfem/pipeline/progress.hpp"
#include "skinfem/pipeline/resources.hpp"

namespace skinfem::pipeline {

void require_linear(const Scene& scene, const std::string& stage) {
  if (scene.material.model != MaterialModel::linear)
    throw SceneError(
        scene.source_path + ": material.model = \"" + to_string(scene.material.model) + "\": " + stage +
        " takes \"linear\" only (the finite-strain skin runs in solve, green, contact, defect and report)");
}

void require_rigid_posts(const Scene& scene) {
  if (scene.sensors.model == SensorModel::post && !scene.sensors.post.support.rigid())
    throw SceneError(scene.source_path +
                     ": sensors.post.support: with material.model \"neo_hookean\" posts are held rigid "
                     "(\"support\": \"rigid\")");
}

std::shared_ptr<Skin> skin_setup(const Scene& scene, MeshPart part, const Border& border) {
  require_linear(scene, "the factored linear skin");
  Stopwatch clock;
  TetMesh mesh = guarded_mesh(scene, part);
  check_sensors_on_skin(scene, mesh);
  return factored_skin(scene, std::move(mesh), clock.seconds(), border);
}

std::shared_ptr<Skin> factored_skin(const Scene& scene, TetMesh mesh, double mesh_seconds,
                                    const Border& border) {
  require_linear(scene, "the factored linear skin");
  auto s = std::make_shared<Skin>();
  s->mesh = std::move(mesh);
  s->wall["mesh"] = mesh_seconds;
  progress("assembling and factoring (" + std::to_string(s->mesh.num_nodes()) + " nodes)");
  ModelOptions options;
  FactorStatus last{};
  options.factor_progress = [&last](const FactorStatus& f) {
    last = f;
    if (f.fraction >= 1) return;  // the line below says it
    char buf[160];
    std::snprintf(buf, sizeof buf, "factoring: ~%.0f %% (%.0f s of ~%.2g s estimated from %.3g flops)",
                  100 * f.fraction, f.elapsed_s, f.estimated_s, f.estimated_flops);
    progress(buf);
  };
  if (border) options.coupling = border(s->mesh);
  s->model = std::make_unique<ElasticModel>(s->mesh, scene.material, scene.geometry.side,
                                            std::vector<Punch>{}, options);
  s->wall["assemble"] = s->model->assemble_seconds();
  s->wall["factor"] = s->model->solver().factor_seconds();
  char buf[200];
  // The estimate is the numerical factorization's (from its flops); the ordering and analysis before it
  // are not in it, and on small meshes they take most of the time.
  if (last.estimated_flops > 0)
    std::snprintf(
        buf, sizeof buf,
        "factored %d DOFs in %.2g s (numerical factorization %.2g s for %.3g flops, estimated %.2g s)",
        s->model->solver().free_dofs(), s->model->solver().factor_seconds(), last.elapsed_s,
        last.estimated_flops, last.estimated_s);
  else
    std::snprintf(buf, sizeof buf, "factored %d DOFs in %.2g s", s->model->solver().free_dofs(),
                  s->model->solver().factor_seconds());
  progress(buf);
  return s;
}

}  // namespace skinfem::pipeline
