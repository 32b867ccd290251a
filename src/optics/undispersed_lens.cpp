#include "optics/undispersed_lens.h"

#include <memory>

namespace objektiv {

namespace {

std::shared_ptr<const Glass> Undispersed(const std::shared_ptr<const Glass>& glass) {
  if (!glass || !glass->IsDispersive()) return glass;
  return std::make_shared<const Glass>(glass->Undispersed());
}

}  // namespace

LensPrescription WithoutDispersion(const LensPrescription& lens) {
  LensPrescription out = lens;
  out.object_medium = Undispersed(lens.object_medium);
  for (LensSurface& s : out.surfaces)
    if (!s.gradient && !s.crystal) s.medium = Undispersed(s.medium);
  return out;
}

bool KeepsDispersionWithout(const LensPrescription& lens) {
  for (const LensSurface& s : lens.surfaces)
    if (s.gradient || s.crystal) return true;
  return false;
}

}  // namespace objektiv
