// Meshes and factors a scene through the installed pipeline library and prints what it built, one
// "key value" per line: nodes, elements, free_dofs.
#include <cstdio>
#include <skinfem/pipeline/skin_setup.hpp>
#include <skinfem/scene/load.hpp>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: downstream SCENE.json\n");
    return 2;
  }
  try {
    const skinfem::Scene scene = skinfem::load_scene(argv[1]);
    const auto skin = skinfem::pipeline::skin_setup(scene);
    std::printf("nodes %d\nelements %d\nfree_dofs %d\n", skin->mesh.num_nodes(), skin->mesh.num_tets(),
                skin->model->solver().free_dofs());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "downstream: %s\n", e.what());
    return 1;
  }
  return 0;
}
