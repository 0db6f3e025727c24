#include "app/skin_setup.hpp"

#include "app/common.hpp"
#include "mesh/build.hpp"

namespace skinfem::app {

std::shared_ptr<Skin> skin_setup(const Scene& scene) {
  auto s = std::make_shared<Skin>();
  Stopwatch clock;
  progress("meshing " + scene.name);
  s->mesh = build_mesh(scene);
  s->wall["mesh"] = clock.seconds();
  progress("assembling and factoring (" + std::to_string(s->mesh.num_nodes()) + " nodes)");
  s->model =
      std::make_unique<ElasticModel>(s->mesh, scene.material, scene.geometry.side, std::vector<Punch>{});
  s->wall["assemble"] = s->model->assemble_seconds();
  s->wall["factor"] = s->model->solver().factor_seconds();
  char buf[128];
  std::snprintf(buf, sizeof buf, "factored %d DOFs in %.1f s", s->model->solver().free_dofs(),
                s->model->solver().factor_seconds());
  progress(buf);
  return s;
}

}  // namespace skinfem::app
