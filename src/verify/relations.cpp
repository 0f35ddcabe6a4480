#include "verify/relations.hpp"

#include <algorithm>
#include <cmath>

#include "verify/inputs.hpp"

namespace doublet::verify {

std::string apply_relations(const std::vector<InputRelation>& relations, std::vector<RelatedInput>& inputs,
                            std::mt19937_64& rng) {
  std::string note;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto find = [&](const std::string& n) -> RelatedInput* {
    for (RelatedInput& i : inputs)
      if (i.name == n) return &i;
    return nullptr;
  };
  for (const InputRelation& r : relations) {
    RelatedInput *a = find(r.a), *b = find(r.b);
    if (!a || !b) continue;  // checked when the harness was planned
    // Redraw the per-sample side; `sign` keeps the offset meaning a - b.
    RelatedInput *derived = a, *base = b;
    double sign = 1;
    if (!a->per_sample && b->per_sample) { derived = b; base = a; sign = -1; }
    const size_t comps = static_cast<size_t>(std::max(derived->components, 1));
    for (size_t k = 0; k < derived->values->size(); ++k) {
      const size_t c = k % comps;
      const size_t from = base->per_sample && base->values->size() == derived->values->size() ? k
                          : c < base->values->size()                                         ? c
                                                                                             : 0;
      const double anchor = (*base->values)[from];
      double x = anchor + sign * r.abs_max * unit(rng);
      const InputSpec s = derived->spec->component(c);
      if (s.lo) x = std::max(x, *s.lo);
      if (s.hi) x = std::min(x, *s.hi);
      x = representable(x, derived->is_double);
      if (std::fabs(x - anchor) > r.abs_max * (1 + 0x1p-40) && note.empty())
        note = "relation " + r.a + " - " + r.b + ": the ranges do not allow |a - b| <= " + std::to_string(r.abs_max) +
               " everywhere; some samples leave the relation";
      (*derived->values)[k] = x;
    }
  }
  return note;
}

}  // namespace doublet::verify
