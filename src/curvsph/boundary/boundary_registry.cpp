// The table of boundary treatments: one line per method.
#include "curvsph/boundary/boundary_model.hpp"
#include "curvsph/boundary/ghost/ghost_boundary.hpp"
#include "curvsph/boundary/integrals/integrals_boundary.hpp"
#include "curvsph/core/error.hpp"

namespace curvsph {
namespace {

template <int D>
struct MethodEntry {
  const char* name;
  std::unique_ptr<BoundaryModel<D>> (*make)(const BoundaryContext<D>&);
};

template <int D>
const std::vector<MethodEntry<D>>& methods() {
  static const std::vector<MethodEntry<D>> table = {
      {"ghost", &make_ghost_boundary<D>},
      {"integrals", &make_integrals_boundary<D>},
  };
  return table;
}

}  // namespace

template <int D>
std::unique_ptr<BoundaryModel<D>> make_boundary_model(const BoundaryContext<D>& ctx) {
  const std::string& method = ctx.spec.boundary.method;
  if (method == "none") return nullptr;
  for (const auto& m : methods<D>())
    if (method == m.name) return m.make(ctx);
  throw InputError(
      ctx.spec.file_name(), "boundary.method",
      "'" + method + "' walls are not available in " + std::to_string(D) + "-D in this build");
}

template std::unique_ptr<BoundaryModel<2>> make_boundary_model<2>(const BoundaryContext<2>&);
template std::unique_ptr<BoundaryModel<3>> make_boundary_model<3>(const BoundaryContext<3>&);

}  // namespace curvsph
