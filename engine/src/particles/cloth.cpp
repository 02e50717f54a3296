#include "particles/cloth.h"

namespace rbsim {

void buildCloth(const ClothDef& cloth, ParticleStore& store, std::vector<ParticleSpring>& springs,
                std::vector<Triangle>& triangles) {
  const int nu = cloth.nu, nv = cloth.nv;
  const double nodeMass = cloth.mass / (nu * nv);
  const std::size_t first = store.count();
  const auto index = [&](int i, int j) { return static_cast<std::uint32_t>(first + static_cast<std::size_t>(j * nu + i)); };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const std::size_t k = store.add();
      store.position[k] = cloth.origin + (double(i) / (nu - 1)) * cloth.edgeU + (double(j) / (nv - 1)) * cloth.edgeV;
      store.inverseMass[k] = 1.0 / nodeMass;
      store.lifetime[k] = kImmortal;
      store.color[k] = cloth.color.cast<float>();
      store.size[k] = 0.0f;
    }
  }
  for (const auto& [i, j] : cloth.pinned) store.inverseMass[index(i, j)] = 0.0;
  const auto connect = [&](int i0, int j0, int i1, int j1, double k) {
    if (i1 < 0 || i1 >= nu || j1 < 0 || j1 >= nv) return;
    ParticleSpring s;
    s.a = index(i0, j0);
    s.b = index(i1, j1);
    s.restLength = (store.position[s.b] - store.position[s.a]).norm();
    s.stiffness = k;
    s.damping = cloth.damping;
    springs.push_back(s);
  };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      connect(i, j, i + 1, j, cloth.stiffness);      // structural
      connect(i, j, i, j + 1, cloth.stiffness);
      connect(i, j, i + 1, j + 1, cloth.stiffness);  // shear
      connect(i, j, i - 1, j + 1, cloth.stiffness);
      connect(i, j, i + 2, j, cloth.bendStiffness);  // bend
      connect(i, j, i, j + 2, cloth.bendStiffness);
      if (i + 1 < nu && j + 1 < nv) {
        triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
        triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
      }
    }
  }
}

}  // namespace rbsim
