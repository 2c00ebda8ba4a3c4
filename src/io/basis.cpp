// The `basis` command's library call (io/basis.hpp).
#include "casteljau/io/basis.hpp"

#include <array>
#include <string>
#include <string_view>

#include "work_limits.hpp"

namespace casteljau::io {

namespace {

constexpr std::array<std::string_view, 7> kind_names = {"bernstein", "bspline",  "lagrange",       "hermite",
                                                        "catmull_rom", "cardinal", "uniform_bspline"};

/// The largest table answered (numbers: (k + 1) x len(t) x functions).
constexpr double max_basis_numbers = 1e7;

}  // namespace

std::span<const std::string_view> basis_kind_names() { return kind_names; }

BasisTable basis(const std::string& kind, std::optional<int> degree, const std::optional<std::vector<double>>& knots,
                 const std::optional<std::vector<double>>& params, std::optional<double> tension, std::span<const double> t,
                 int k) {
  std::size_t index = kind_names.size();
  for (std::size_t i = 0; i < kind_names.size(); ++i)
    if (kind_names[i] == kind) index = i;
  if (index == kind_names.size()) {
    std::string list;
    for (const auto n : kind_names) list += (list.empty() ? "" : ", ") + std::string(n);
    throw InvalidArgument("kind", "unknown basis kind '" + kind + "' (" + list + ")");
  }
  BasisSpec b;
  b.kind = static_cast<BasisKind>(index);
  const bool wants_degree = b.kind == BasisKind::bernstein || b.kind == BasisKind::bspline;
  const bool wants_knots = b.kind == BasisKind::bspline, wants_params = b.kind == BasisKind::lagrange;
  const bool wants_tension = b.kind == BasisKind::cardinal;
  const auto field = [&](bool given, bool wanted, const char* name) {
    if (given && !wanted) throw InvalidArgument(name, "the " + kind + " basis has no " + name + " (it belongs to another kind)");
    if (!given && wanted) throw InvalidArgument(name, "required field is missing: the " + kind + " basis needs " + name);
  };
  field(degree.has_value(), wants_degree, "degree");
  field(knots.has_value(), wants_knots, "knots");
  field(params.has_value(), wants_params, "params");
  field(tension.has_value(), wants_tension, "tension");
  if (degree) b.degree = *degree;
  if (knots) b.knots = *knots;
  if (params) b.params = *params;
  if (tension) b.tension = *tension;
  if (k < 0) throw InvalidArgument("derivatives", "must be >= 0, got " + std::to_string(k));
  check_basis(b);
  const double numbers = (static_cast<double>(k) + 1) * static_cast<double>(t.size()) * static_cast<double>(basis_count(b));
  if (numbers > max_basis_numbers) {
    throw InvalidArgument("t", "the table would hold " + limits::amount_text(numbers) +
                                   " numbers ((derivatives + 1) x len(t) x functions), more than the limit of 10000000");
  }
  if (b.kind == BasisKind::lagrange && numbers * static_cast<double>(b.params.size()) > 100 * max_basis_numbers) {
    throw InvalidArgument("params", "the Lagrange table would take about " +
                                        limits::amount_text(numbers * static_cast<double>(b.params.size())) +
                                        " operations ((derivatives + 1) x len(t) x len(params)^2), more than the limit of 1000000000");
  }
  return basis_table(b, t, k);
}

}  // namespace casteljau::io
