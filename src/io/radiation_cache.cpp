#include "io/radiation_cache.hpp"

#include <functional>
#include <map>
#include <mutex>
#include <sstream>

#include "dynamics/rail_model.hpp"
#include "io/cache_files.hpp"
#include "io/wheel_modes_cache.hpp"

namespace rollnoise::io {
namespace {

constexpr const char* kWheelMagic = "rollnoise wheel radiation 2\n";
constexpr const char* kRailMagic = "rollnoise rail radiation 1\n";
constexpr const char* kLineMagic = "rollnoise rail line gram 1\n";
constexpr const char* kSectionMagic = "rollnoise rail section table 1\n";
constexpr const char* kSectionGramMagic = "rollnoise rail section gram 2\n";

void put_matrices(std::string& out, const std::vector<Eigen::MatrixXcd>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  for (const Eigen::MatrixXcd& m : v) {
    put(out, static_cast<std::int64_t>(m.rows()));
    for (Eigen::Index i = 0; i < m.size(); ++i) put(out, m(i));
  }
}
bool get_matrices(Bytes& in, std::vector<Eigen::MatrixXcd>& v) {
  std::uint64_t n = 0;
  if (!in.get(n) || n > 100000) return false;
  v.clear();
  for (std::uint64_t k = 0; k < n; ++k) {
    std::int64_t rows = 0;
    if (!in.get(rows) || rows < 0 || rows > 1000) return false;
    Eigen::MatrixXcd m(rows, rows);
    for (Eigen::Index i = 0; i < m.size(); ++i)
      if (!in.get(m(i))) return false;
    v.push_back(std::move(m));
  }
  return true;
}

void put_beam(std::ostringstream& k, const dynamics::BeamSection& b) {
  k << real_text(b.youngs_modulus) << " " << real_text(b.shear_modulus) << " " << real_text(b.area)
    << " " << real_text(b.second_moment) << " " << real_text(b.mass_per_length) << " "
    << real_text(b.shear_coefficient) << " " << real_text(b.loss_factor) << " " << b.timoshenko
    << "\n";
}
void put_support(std::ostringstream& k, const dynamics::Support& s) {
  k << real_text(s.pad_stiffness) << " " << real_text(s.pad_loss_factor) << " "
    << real_text(s.sleeper_mass) << " " << real_text(s.ballast_stiffness) << " "
    << real_text(s.ballast_loss_factor) << "\n";
}

void put_doubles(std::string& out, const std::vector<double>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  for (double x : v) put(out, x);
}
bool get_doubles(Bytes& in, std::vector<double>& v) {
  std::uint64_t n = 0;
  if (!in.get(n) || n > in.left() / sizeof(double)) return false;
  v.resize(n);
  for (double& x : v)
    if (!in.get(x)) return false;
  return true;
}

std::string grid_text(const std::vector<double>& grid, const acoustics::Fluid& fluid) {
  std::ostringstream key;
  key << "rho " << real_text(fluid.density) << " c " << real_text(fluid.sound_speed) << "\ngrid "
      << grid.size();
  for (double f : grid) key << " " << real_text(f);
  key << "\n";
  return key.str();
}

std::string wheel_payload(const pipeline::WheelRadiation& w) {
  std::string out;
  put_doubles(out, w.frequency);
  put(out, w.surface);
  put(out, static_cast<std::int64_t>(w.elements));
  put(out, static_cast<std::uint64_t>(w.orders.size()));
  for (const auto& o : w.orders) {
    put(out, static_cast<std::int64_t>(o.n));
    put(out, static_cast<std::uint64_t>(o.modes.size()));
    for (int k : o.modes) put(out, static_cast<std::int64_t>(k));
    for (const Eigen::MatrixXcd& P : o.power)
      for (Eigen::Index i = 0; i < P.size(); ++i) put(out, P(i));
  }
  put(out, static_cast<std::uint64_t>(w.efficiency.size()));
  for (const auto& s : w.efficiency) put_doubles(out, s);
  for (std::size_t j = 0; j < w.efficiency.size(); ++j) {
    put(out, static_cast<std::int64_t>(w.family[j]));
    put(out, static_cast<std::int64_t>(w.nodal_circles[j]));
  }
  return out;
}

std::optional<pipeline::WheelRadiation> parse_wheel(const std::string& body) {
  Bytes in(body);
  pipeline::WheelRadiation w;
  std::int64_t elements = 0;
  std::uint64_t orders = 0;
  if (!get_doubles(in, w.frequency) || !in.get(w.surface) || !in.get(elements) || !in.get(orders))
    return std::nullopt;
  w.elements = static_cast<int>(elements);
  if (orders > 1000) return std::nullopt;
  for (std::uint64_t i = 0; i < orders; ++i) {
    pipeline::WheelRadiation::Order o;
    std::int64_t n = 0;
    std::uint64_t m = 0;
    if (!in.get(n) || !in.get(m) || m > 10000) return std::nullopt;
    o.n = static_cast<int>(n);
    for (std::uint64_t j = 0; j < m; ++j) {
      std::int64_t k = 0;
      if (!in.get(k)) return std::nullopt;
      o.modes.push_back(static_cast<int>(k));
    }
    for (std::size_t f = 0; f < w.frequency.size(); ++f) {
      Eigen::MatrixXcd P(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
      for (Eigen::Index e = 0; e < P.size(); ++e)
        if (!in.get(P(e))) return std::nullopt;
      o.power.push_back(std::move(P));
    }
    w.orders.push_back(std::move(o));
  }
  std::uint64_t ne = 0;
  if (!in.get(ne) || ne > 100000) return std::nullopt;
  w.efficiency.resize(ne);
  for (auto& s : w.efficiency)
    if (!get_doubles(in, s)) return std::nullopt;
  for (std::uint64_t j = 0; j < ne; ++j) {
    std::int64_t family = 0, circles = 0;
    if (!in.get(family) || !in.get(circles)) return std::nullopt;
    w.family.push_back(static_cast<int>(family));
    w.nodal_circles.push_back(static_cast<int>(circles));
  }
  if (in.left() != 0) return std::nullopt;
  return w;
}

std::string rail_payload(const pipeline::RailRadiation& r) {
  std::string out;
  put(out, static_cast<std::int64_t>(r.ground ? 1 : 0));
  for (const auto* v : {&r.frequency, &r.vertical, &r.lateral, &r.sigma_vertical, &r.sigma_lateral})
    put_doubles(out, *v);
  return out;
}

std::optional<pipeline::RailRadiation> parse_rail(const std::string& body) {
  Bytes in(body);
  pipeline::RailRadiation r;
  std::int64_t ground = 0;
  if (!in.get(ground)) return std::nullopt;
  r.ground = ground != 0;
  for (auto* v : {&r.frequency, &r.vertical, &r.lateral, &r.sigma_vertical, &r.sigma_lateral})
    if (!get_doubles(in, *v)) return std::nullopt;
  if (in.left() != 0) return std::nullopt;
  return r;
}

}  // namespace

std::string rail_identity(const std::string& model, const dynamics::TrackParameters& t) {
  std::ostringstream k;
  k << model << "\n";
  put_beam(k, t.vertical);
  put_beam(k, t.lateral);
  put_support(k, t.vertical_support);
  put_support(k, t.lateral_support);
  put_support(k, t.longitudinal_support);
  k << real_text(t.sleeper_spacing) << " " << real_text(t.head_height) << " "
    << t.supports_each_side << " " << static_cast<int>(t.discrete_solution) << "\n";
  return k.str();
}

namespace {

// One table: from this process's memo (a study's cases, a test's runs) under `memo`, else from the
// cache file `prefix`-<hash of key> in `directory` (none: no file), else made; kept in both. The
// memo is one per kind of table T.
template <class T, class Parse, class Payload, class Make>
std::shared_ptr<const T> kept_or_made(const std::string& memo,
                                      const std::optional<std::string>& directory,
                                      const std::string& key, const char* prefix, const char* magic,
                                      const char* what, const Parse& parse, const Payload& payload,
                                      const Make& make) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const T>> kept;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = kept.find(memo); it != kept.end()) return it->second;
  }
  std::shared_ptr<const T> t;
  const bool filed = directory && !key.empty();
  if (filed)
    if (const auto body = read_cache_payload(cache_file(*directory, prefix, key), magic, key))
      if (std::optional<T> read = parse(*body)) t = std::make_shared<const T>(std::move(*read));
  if (!t) {
    t = std::make_shared<const T>(make());
    if (filed)
      write_cache_payload(cache_file(*directory, prefix, key), magic, key, payload(*t), what);
  }
  std::lock_guard<std::mutex> lock(mutex);
  kept.emplace(memo, t);
  return t;
}

// The key of a cache file: this build and `text`; empty (no file) when the build is unknown.
std::string build_key(const std::optional<std::string>& directory, const std::string& text) {
  const std::string build = directory ? build_identity() : std::string();
  return build.empty() ? std::string() : build + text;
}

}  // namespace

std::shared_ptr<const pipeline::RailLineGram> rail_line_gram_cached(
    const dynamics::RailModel& rail, const std::string& identity,
    const std::vector<double>& positions, const std::vector<double>& grid, int gauss, int threads) {
  std::ostringstream k;
  k << identity << "positions";
  for (double x : positions) k << " " << real_text(x);
  k << "\ngauss " << gauss << "\n" << grid_text(grid, acoustics::Fluid{});
  const std::optional<std::string> directory = cache_directory();
  const auto parse = [&](const std::string& body) -> std::optional<pipeline::RailLineGram> {
    Bytes in(body);
    pipeline::RailLineGram r;
    r.positions = positions;
    if (get_matrices(in, r.z) && get_matrices(in, r.y) && get_matrices(in, r.sleepers) &&
        in.left() == 0 && r.z.size() == grid.size())
      return r;
    return std::nullopt;
  };
  const auto payload = [](const pipeline::RailLineGram& g) {
    std::string out;
    put_matrices(out, g.z);
    put_matrices(out, g.y);
    put_matrices(out, g.sleepers);
    return out;
  };
  return kept_or_made<pipeline::RailLineGram>(
      k.str(), directory, build_key(directory, k.str()), "rail-line-gram", kLineMagic,
      "rail line gram", parse, payload,
      [&] { return pipeline::rail_line_gram(rail, positions, grid, gauss, threads); });
}

namespace {

std::string outline_text(const std::vector<Eigen::Vector2d>& outline, bool ground) {
  std::ostringstream k;
  k << "section " << outline.size();
  for (const auto& p : outline) k << " " << real_text(p.x()) << " " << real_text(p.y());
  k << "\nground " << (ground ? 1 : 0) << "\n";
  return k.str();
}

std::string table_payload(const pipeline::SectionRadiationTable& t) {
  std::string out;
  put(out, static_cast<std::uint64_t>(t.ground ? 1 : 0));
  put(out, t.step);
  put(out, static_cast<std::uint64_t>(t.pieces.size()));
  for (const dynamics::OutlinePiece& p : t.pieces)
    for (const Eigen::Vector2d* v : {&p.start, &p.end, &p.normal})
      put(out, v->x()), put(out, v->y());
  put(out, static_cast<std::int64_t>(t.patterns.cols()));
  for (Eigen::Index i = 0; i < t.patterns.size(); ++i) put(out, t.patterns(i));
  put_matrices(out, t.power);
  return out;
}

std::optional<pipeline::SectionRadiationTable> parse_table(const std::string& body) {
  Bytes in(body);
  pipeline::SectionRadiationTable t;
  std::uint64_t ground = 0, pieces = 0;
  std::int64_t r = 0;
  if (!in.get(ground) || !in.get(t.step) || !in.get(pieces) || pieces > 10000) return std::nullopt;
  t.ground = ground != 0;
  t.pieces.resize(pieces);
  for (dynamics::OutlinePiece& p : t.pieces)
    for (Eigen::Vector2d* v : {&p.start, &p.end, &p.normal})
      if (!in.get((*v)(0)) || !in.get((*v)(1))) return std::nullopt;
  if (!in.get(r) || r < 0 || r > static_cast<std::int64_t>(pieces)) return std::nullopt;
  t.patterns.resize(static_cast<Eigen::Index>(pieces), r);
  for (Eigen::Index i = 0; i < t.patterns.size(); ++i)
    if (!in.get(t.patterns(i))) return std::nullopt;
  if (!get_matrices(in, t.power) || in.left() != 0 || t.power.size() < 2) return std::nullopt;
  for (const Eigen::MatrixXcd& m : t.power)
    if (m.rows() != r) return std::nullopt;
  return t;
}

}  // namespace

std::shared_ptr<const pipeline::SectionRadiationTable> section_radiation_table_cached(
    const std::vector<Eigen::Vector2d>& outline, bool ground, double max_k,
    const acoustics::Fluid& fluid, int threads) {
  const std::string k =
      outline_text(outline, ground) + "max_k " + real_text(max_k) + "\n" + grid_text({}, fluid);
  const std::optional<std::string> directory = cache_directory();
  return kept_or_made<pipeline::SectionRadiationTable>(
      k, directory, build_key(directory, k), "rail-section-table", kSectionMagic,
      "rail section table", parse_table, table_payload,
      [&] { return pipeline::section_radiation_table(outline, ground, max_k, fluid, threads); });
}

namespace {

// Gram matrices on `grid` under `what` (the loads) beside the rail's identity and the table: from
// the cache, else made and stored.
std::vector<Eigen::MatrixXcd> grams_cached(
    const std::string& identity, const std::string& what, const char* file_prefix,
    const pipeline::SectionRadiationTable& table, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, const std::function<std::vector<Eigen::MatrixXcd>()>& make) {
  std::ostringstream k;
  k << identity << what;
  // the table: its air and ground, elements and reach (its values follow from them and the build)
  k << "\ntable " << table.ground << " " << table.pieces.size() << " " << table.patterns.cols()
    << " " << real_text(table.max_wavenumber()) << "\n"
    << grid_text(grid, fluid);
  using Grams = std::vector<Eigen::MatrixXcd>;
  const std::optional<std::string> directory = cache_directory();
  const auto parse = [&](const std::string& body) -> std::optional<Grams> {
    Bytes in(body);
    Grams g;
    if (get_matrices(in, g) && in.left() == 0 && g.size() == grid.size()) return g;
    return std::nullopt;
  };
  const auto payload = [](const Grams& g) {
    std::string out;
    put_matrices(out, g);
    return out;
  };
  return *kept_or_made<Grams>(k.str(), directory, build_key(directory, k.str()), file_prefix,
                              kSectionGramMagic, "rail section gram", parse, payload, make);
}

}  // namespace

std::vector<Eigen::MatrixXcd> basis_section_grams_cached(
    const dynamics::RailModel& rail, const std::string& identity, const std::vector<double>& x,
    const pipeline::SectionRadiationTable& table, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads) {
  std::ostringstream what;
  what << "the load basis at";
  for (double p : x) what << " " << real_text(p);
  return grams_cached(identity, what.str(), "rail-basis-section-gram", table, grid, fluid, [&] {
    return pipeline::basis_section_grams(rail, x, table, grid, fluid, threads);
  });
}

std::vector<Eigen::MatrixXcd> section_grams_cached(
    const dynamics::RailModel& rail, const std::string& identity,
    const std::vector<dynamics::RailLoadPoint>& points,
    const pipeline::SectionRadiationTable& table, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads) {
  std::ostringstream what;
  what << "loads";
  for (const dynamics::RailLoadPoint& p : points)
    what << " " << real_text(p.offset_y) << " " << real_text(p.contact_angle) << " "
         << real_text(p.x);
  return grams_cached(identity, what.str(), "rail-section-gram", table, grid, fluid, [&] {
    return pipeline::section_grams(
        rail, points, table, grid, fluid, threads, [&](const std::vector<double>& x) {
          return basis_section_grams_cached(rail, identity, x, table, grid, fluid, threads);
        });
  });
}

std::shared_ptr<const pipeline::WheelRadiation> wheel_radiation_cached(
    const WheelFeCase& c, int n_min, const std::vector<double>& grid, const acoustics::Fluid& fluid,
    bool cache, int threads) {
  const std::string text = "n_min " + std::to_string(n_min) + "\n" + grid_text(grid, fluid);
  const std::optional<std::string> directory = cache ? cache_directory() : std::nullopt;
  const std::string modes_key = directory ? mode_cache_key(c) : std::string();
  return kept_or_made<pipeline::WheelRadiation>(
      c.id + "\n" + text, directory, modes_key.empty() ? modes_key : modes_key + text,
      "wheel-radiation", kWheelMagic, "wheel radiation", parse_wheel, wheel_payload, [&] {
        return pipeline::wheel_radiation(*wheel_fe_modes_once(c), n_min, grid, fluid, threads);
      });
}

std::shared_ptr<const pipeline::RailRadiation> rail_radiation_cached(
    const std::vector<Eigen::Vector2d>& outline, bool ground, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads) {
  const std::string k = outline_text(outline, ground) + grid_text(grid, fluid);
  const std::optional<std::string> directory = cache_directory();
  return kept_or_made<pipeline::RailRadiation>(
      k, directory, build_key(directory, k), "rail-radiation", kRailMagic, "rail radiation",
      parse_rail, rail_payload,
      [&] { return pipeline::rail_radiation(outline, ground, grid, fluid, threads); });
}

}  // namespace rollnoise::io
