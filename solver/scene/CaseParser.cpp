#include "scene/CaseParser.h"

#include <toml++/toml.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/Memory.h"
#include "physics/SlideMotion.h"
#include "scene/Geometry.h"

namespace wcmps {
namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date or time";
  }
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// Reads one table of the case file. Every key it is asked about counts as known; finish()
/// rejects the others.
class TableReader {
 public:
  TableReader(const toml::table& t, std::string label, const std::string& file)
      : t_(t), label_(std::move(label)), file_(file) {}

  SourceLocation where(const toml::node& n) const {
    return {file_, n.source().begin.line, n.source().begin.column};
  }
  SourceLocation where() const { return where(t_); }
  [[noreturn]] void fail(const toml::node& n, const std::string& key,
                         const std::string& msg) const {
    throw CaseError(where(n), label_ + " " + key + ": " + msg);
  }

  /// Fails naming `key` at its place in the file, or at the table's if the key is not given
  /// (its default is what is wrong).
  [[noreturn]] void fail_key(const std::string& key, const std::string& msg) const {
    if (const toml::node* n = t_.get(key)) fail(*n, key, msg);
    throw CaseError(where(), label_ + " " + key + ": " + msg);
  }

  const toml::node* get(const std::string& key) {
    known_.push_back(key);
    return t_.get(key);
  }

  double number(const std::string& key, std::optional<double> fallback, double lo, double hi,
                bool lo_open = false, bool hi_open = false) {
    const toml::node* n = get(key);
    if (!n) {
      if (!fallback) throw CaseError(where(), label_ + " " + key + " is required");
      return *fallback;
    }
    return number_value(*n, key, lo, hi, lo_open, hi_open);
  }

  std::optional<double> optional_number(const std::string& key, double lo, double hi,
                                        bool lo_open = false) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return number_value(*n, key, lo, hi, lo_open, false);
  }

  double number_value(const toml::node& n, const std::string& key, double lo, double hi,
                      bool lo_open, bool hi_open) const {
    if (!n.is_number()) fail(n, key, "expected a number, got " + type_name(n));
    const double v = n.value<double>().value_or(NAN);
    if (!std::isfinite(v)) fail(n, key, "must be finite");
    const bool below = lo_open ? !(v > lo) : !(v >= lo);
    const bool above = hi_open ? !(v < hi) : !(v <= hi);
    if (below || above) {
      std::string range = std::string(lo_open ? "(" : "[") + fmt(lo) + ", " +
                          (std::isinf(hi) ? std::string("inf") : fmt(hi)) +
                          (hi_open || std::isinf(hi) ? ")" : "]");
      fail(n, key, "value " + fmt(v) + " is out of range " + range);
    }
    return v;
  }

  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo,
                       std::int64_t hi) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_integer()) fail(*n, key, "expected an integer, got " + type_name(*n));
    const std::int64_t v = n->value<std::int64_t>().value_or(0);
    if (v < lo || v > hi) {
      fail(*n, key,
           "value " + std::to_string(v) + " is out of range [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "]");
    }
    return v;
  }

  bool boolean(const std::string& key, bool fallback) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(*n, key, "expected true or false, got " + type_name(*n));
    return n->value<bool>().value_or(fallback);
  }

  std::string string(const std::string& key, const std::string& fallback) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_string()) fail(*n, key, "expected a string, got " + type_name(*n));
    return n->value<std::string>().value_or(fallback);
  }

  /// A string that must be one of `choices`.
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& choices) {
    const std::string v = string(key, fallback);
    for (const auto& c : choices) {
      if (v == c) return v;
    }
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
    fail_key(key, "\"" + v + "\" is not one of " + list);
  }

  Vec2 point_value(const toml::node& n, const std::string& key) const {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 2 || !(*a)[0].is_number() || !(*a)[1].is_number()) {
      fail(n, key, "expected a point [x, y] of two numbers");
    }
    const Vec2 p{(*a)[0].value<double>().value_or(NAN), (*a)[1].value<double>().value_or(NAN)};
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(n, key, "coordinates must be finite");
    return p;
  }

  std::optional<Vec2> point(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return point_value(*n, key);
  }

  std::vector<Vec2> points(const toml::node& n, const std::string& key, std::size_t min_count) {
    const toml::array* a = n.as_array();
    if (!a) fail(n, key, "expected an array of points [[x, y], ...], got " + type_name(n));
    std::vector<Vec2> out;
    for (const auto& e : *a) out.push_back(point_value(e, key));
    if (out.size() < min_count) {
      fail(n, key, "needs at least " + std::to_string(min_count) + " points");
    }
    return out;
  }

  const toml::array* array(const std::string& key) {
    const toml::node* n = get(key);
    if (!n) return nullptr;
    if (!n->is_array()) fail(*n, key, "expected an array, got " + type_name(*n));
    return n->as_array();
  }

  /// Rejects keys nobody asked about.
  void finish() const {
    for (auto&& [k, v] : t_) {
      bool ok = false;
      for (const auto& kk : known_) ok = ok || kk == k.str();
      if (!ok) {
        std::string list;
        for (const auto& kk : known_) list += (list.empty() ? "" : ", ") + kk;
        throw CaseError({file_, k.source().begin.line, k.source().begin.column},
                        "unknown key '" + std::string(k.str()) + "' in " + label_ +
                            " (known keys: " + list + ")");
      }
    }
  }

  const toml::table& table() const { return t_; }
  const std::string& label() const { return label_; }
  const std::string& file() const { return file_; }

 private:
  const toml::table& t_;
  std::string label_;
  const std::string& file_;
  std::vector<std::string> known_;
};

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A sub-table [name] of the root (an empty one if absent).
const toml::table& section(TableReader& root, const std::string& name, const toml::table& empty) {
  const toml::node* n = root.get(name);
  if (!n) return empty;
  if (!n->is_table()) root.fail(*n, name, "expected a table [" + name + "]");
  return *n->as_table();
}

std::vector<Vec2> rectangle_corners(TableReader& r, const toml::node& n, const std::string& key) {
  const toml::table* t = n.as_table();
  if (!t) r.fail(n, key, "expected { min = [x, y], max = [x, y] }");
  TableReader rect(*t, r.label() + " " + key, r.file());
  const auto lo = rect.point("min");
  const auto hi = rect.point("max");
  if (!lo || !hi) r.fail(n, key, "needs both min and max");
  rect.finish();
  if (!(hi->x > lo->x) || !(hi->y > lo->y)) {
    r.fail(n, key, "max must be greater than min in x and in y");
  }
  return {*lo, {hi->x, lo->y}, *hi, {lo->x, hi->y}};
}

FluidRegionSpec read_fluid(TableReader& r) {
  FluidRegionSpec f;
  f.where = r.where();
  f.label = r.label();
  const toml::node* rect = r.get("rectangle");
  const toml::node* poly = r.get("polygon");
  if ((rect != nullptr) == (poly != nullptr)) {
    throw CaseError(r.where(), r.label() + ": give exactly one shape, rectangle or polygon");
  }
  if (rect) {
    f.polygon = rectangle_corners(r, *rect, "rectangle");
  } else {
    f.polygon = r.points(*poly, "polygon", 3);
    if (std::abs(signed_area(f.polygon)) <= 0.0) r.fail(*poly, "polygon", "has zero area");
  }
  f.velocity = r.point("velocity").value_or(Vec2{});
  r.finish();
  return f;
}

WallSpec read_wall(TableReader& r) {
  WallSpec w;
  w.where = r.where();
  w.label = r.label();
  const toml::node* line = r.get("polyline");
  const toml::node* rect = r.get("rectangle");
  const toml::node* poly = r.get("polygon");
  const int shapes = (line != nullptr) + (rect != nullptr) + (poly != nullptr);
  if (shapes != 1) {
    throw CaseError(r.where(),
                    r.label() + ": give exactly one shape, polyline, rectangle or polygon");
  }
  const bool closed = r.boolean("closed", false);
  const toml::node* solid_node = r.get("solid");
  if (line) {
    w.points = r.points(*line, "polyline", 2);
    w.closed = closed;
    if (!solid_node) {
      throw CaseError(r.where(), r.label() +
                                     ": a polyline wall needs solid = \"left\" or \"right\" "
                                     "(the side of the solid, looking along the line)");
    }
    const std::string side = r.choice("solid", "right", {"left", "right"});
    w.solid_on_right = side == "right";
  } else {
    if (solid_node) {
      r.fail(*solid_node, "solid",
             "only a polyline takes solid; rectangles and polygons are solid inside");
    }
    w.points = rect ? rectangle_corners(r, *rect, "rectangle") : r.points(*poly, "polygon", 3);
    w.closed = true;
    const double a = signed_area(w.points);
    if (a == 0.0) r.fail(poly ? *poly : *rect, poly ? "polygon" : "rectangle", "has zero area");
    // Solid inside: on the right of a clockwise outline, on the left of a counter-clockwise one.
    w.solid_on_right = a < 0.0;
  }
  for (std::size_t i = 0; i + 1 < w.points.size() + (w.closed ? 1 : 0); ++i) {
    const Vec2 a = w.points[i], b = w.points[(i + 1) % w.points.size()];
    if (norm(b - a) == 0.0) {
      throw CaseError(r.where(),
                      r.label() + ": segment " + std::to_string(i + 1) + " has zero length");
    }
  }
  r.finish();
  return w;
}

/// [tank]: a beach tank, expanded into its wall (bed, bottom, far wall) and its water.
void read_tank(TableReader& r, CaseSpec& c) {
  TankSpec t;
  t.where = r.where();
  t.slope_deg = r.number("slope", std::nullopt, 0.0, 90.0, true, true);
  t.depth = r.number("depth", std::nullopt, 0.0, kInf, true);
  t.length = r.number("length", std::nullopt, 0.0, kInf, true);
  t.freeboard = r.number("freeboard", 0.1, 0.0, kInf, true);
  const double tan_a = std::tan(t.slope_deg * std::acos(-1.0) / 180.0);
  const double toe = t.depth / tan_a;  // where the bed meets the bottom
  if (!(t.length > toe)) {
    r.fail_key("length", "the bed reaches the bottom " + fmt(toe) +
                             " m from the shoreline, at or beyond the " +
                             "far wall: make the tank longer or the slope steeper");
  }
  r.finish();
  WallSpec wall;
  wall.points = {{-t.freeboard / tan_a, t.freeboard},
                 {toe, -t.depth},
                 {t.length, -t.depth},
                 {t.length, t.freeboard}};
  wall.solid_on_right = true;  // going down the bed, the ground is on the right
  wall.where = t.where;
  wall.label = "[tank]";
  c.walls.push_back(wall);
  FluidRegionSpec water;
  water.polygon = {{0.0, 0.0}, {toe, -t.depth}, {t.length, -t.depth}, {t.length, 0.0}};
  water.where = t.where;
  water.label = "[tank]";
  c.fluids.push_back(water);
  c.tank = t;
}

/// [block.motion]: how the body moves.
BodyMotionSpec read_motion(TableReader& r) {
  BodyMotionSpec m;
  m.where = r.where();
  const std::string type = r.choice("type", "fixed", {"fixed", "table", "ln-cosh", "free"});
  if (type == "table") {
    m.type = BodyMotionType::Table;
    const toml::array* t = r.array("times");
    const toml::array* s = r.array("distances");
    if (!t || !s)
      throw CaseError(r.where(), r.label() + ": type \"table\" needs times and distances");
    for (const auto& e : *t) {
      m.times.push_back(r.number_value(e, "times", -kInf, kInf, false, false));
      if (m.times.size() > 1 && !(m.times.back() > m.times[m.times.size() - 2])) {
        r.fail(e, "times", "must be increasing");
      }
    }
    for (const auto& e : *s)
      m.distances.push_back(r.number_value(e, "distances", -kInf, kInf, false, false));
    if (m.times.size() != m.distances.size() || m.times.size() < 2) {
      r.fail_key("distances", "needs one distance per time, at least two (" +
                                  std::to_string(m.times.size()) + " times, " +
                                  std::to_string(m.distances.size()) + " distances)");
    }
    try {
      SplineSlide check(m.times, m.distances);
    } catch (const std::invalid_argument& e) {
      r.fail_key("distances", e.what());
    }
  } else if (type == "ln-cosh") {
    m.type = BodyMotionType::LnCosh;
    m.a0 = r.number("a0", std::nullopt, 0.0, kInf, true);
    m.ut = r.number("ut", std::nullopt, 0.0, kInf, true);
  } else if (type == "free") {
    m.type = BodyMotionType::Free;
    m.friction = r.number("friction", std::nullopt, 0.0, kInf);
  } else {
    m.type = BodyMotionType::Fixed;
  }
  r.finish();
  return m;
}

/// [block]: the study's triangular block, on the bed of the [tank], added as a solid polygon.
void read_block(TableReader& r, CaseSpec& c) {
  BlockSpec b;
  b.where = r.where();
  if (!c.tank) throw CaseError(r.where(), "[block] sits on the bed of a [tank]: give one");
  const TankSpec& t = *c.tank;
  b.top_length = r.number("top_length", std::nullopt, 0.0, kInf, true);
  b.angle_a_deg = r.number("angle_a", 100.0, 0.0, 180.0, true, true);
  b.top_depth = r.number("top_depth", std::nullopt, 0.0, t.depth, true, true);
  b.density = r.number("density", std::nullopt, 0.0, kInf, true);
  const double deg = std::acos(-1.0) / 180.0;
  const double alpha = t.slope_deg * deg, angle_a = b.angle_a_deg * deg;
  const double angle_g = std::acos(-1.0) - alpha - angle_a;
  if (!(angle_g > 0.0)) {
    r.fail_key("angle_a",
               "with the bed's " + fmt(t.slope_deg) + " degrees at C, the angles leave none for G");
  }
  // C on the bed at the top's depth; A along the horizontal top; G down the bed from C, at
  // CG = CA sin(A) / sin(G) (law of sines).
  b.c = {b.top_depth / std::tan(alpha), -b.top_depth};
  b.a = b.c + Vec2{b.top_length, 0.0};
  const double cg = b.top_length * std::sin(angle_a) / std::sin(angle_g);
  b.g = b.c + Vec2{std::cos(alpha), -std::sin(alpha)} * cg;
  if (b.g.y <= -t.depth) {
    r.fail_key("top_length",
               "the block's corner G (" + fmt(b.g.x) + ", " + fmt(b.g.y) +
                   ") m lies below the toe of the bed: the block does not fit on the slope");
  }
  if (b.a.x >= t.length) r.fail_key("top_length", "reaches the far wall");
  BodySpec body;
  body.density = b.density;
  body.downslope = {std::cos(alpha), -std::sin(alpha)};
  body.bed_normal = {std::sin(alpha), std::cos(alpha)};
  body.label = "[block]";
  if (const toml::node* n = r.get("motion")) {
    if (!n->is_table()) r.fail(*n, "motion", "expected a table [block.motion]");
    TableReader m(*n->as_table(), "[block.motion]", r.file());
    body.motion = read_motion(m);
  } else {
    body.motion.type = BodyMotionType::Fixed;
    body.motion.where = b.where;
  }
  r.finish();
  body.wall = c.walls.size();
  WallSpec w;
  w.points = {b.c, b.a, b.g};
  w.closed = true;
  w.solid_on_right = true;  // C -> A -> G runs clockwise
  w.where = b.where;
  w.label = "[block]";
  c.walls.push_back(w);
  c.block = b;
  c.body = body;
}

/// [post]: what `wcmps post` computes, and how.
PostSpec read_post(TableReader& r, const CaseSpec& c) {
  PostSpec p;
  static const std::pair<const char*, PostProduct> kProducts[] = {
      {"grid", PostProduct::Grid},
      {"sections", PostProduct::Sections},
      {"section_averages", PostProduct::SectionAverages},
      {"free_surface", PostProduct::FreeSurface},
      {"lines", PostProduct::Lines},
      {"cavity", PostProduct::Cavity}};
  if (const toml::array* a = r.array("products")) {
    for (const auto& e : *a) {
      const auto name = e.value<std::string>();
      std::optional<PostProduct> found;
      std::string list;
      for (const auto& [key, product] : kProducts) {
        if (name && *name == key) found = product;
        list += (list.empty() ? "" : ", ") + std::string(key);
      }
      if (!found) {
        r.fail(e, "products",
               "unknown product " + (name ? "\"" + *name + "\"" : type_name(e)) +
                   " (products: " + list + ")");
      }
      if (*found == PostProduct::Sections && c.sections.empty()) {
        r.fail(e, "products", "\"sections\" needs [[section]] tables");
      }
      if ((*found == PostProduct::SectionAverages || *found == PostProduct::Lines) && !c.block) {
        r.fail(e, "products", "\"" + *name + "\" is measured along the block: it needs a [block]");
      }
      p.products.push_back(*found);
    }
  }
  if (const toml::array* a = r.array("times")) {
    for (const auto& e : *a) {
      const double t = r.number_value(e, "times", 0.0, c.end_time, false, false);
      if (!p.times.empty() && t <= p.times.back()) {
        r.fail(e, "times", "must be increasing (" + fmt(t) + " after " + fmt(p.times.back()) + ")");
      }
      p.times.push_back(t);
    }
  }
  p.grid_spacing = r.number("grid_spacing", 0.0, 0.0, kInf);
  if (const toml::array* a = r.array("grid_fields")) {
    for (const auto& e : *a) {
      const auto name = e.value<std::string>();
      // The frames' floating-point fields, and what vtkMPSSpeedVorticity adds to them.
      const bool known = name && (*name == "speed" || *name == "vorticity" || *name == "velocity" ||
                                  *name == "pressure" || *name == "number_density");
      if (!known) {
        r.fail(e, "grid_fields",
               "unknown field " + (name ? "\"" + *name + "\"" : type_name(e)) +
                   " (fields: velocity, pressure, number_density, speed, vorticity)");
      }
      p.grid_fields.push_back(*name);
    }
  }
  p.corrected_gradient = r.choice("vorticity", "mps", {"mps", "corrected"}) == "corrected";
  p.section_samples = static_cast<int>(r.integer("section_samples", 51, 2, 100000));
  p.average_max_x_over_l = r.number("average_max_x_over_l", 3.5, 0.0, kInf, true);
  p.average_stations = static_cast<int>(r.integer("average_stations", 36, 2, 100000));
  p.surface_spacing = r.number("surface_spacing", 0.0, 0.0, kInf);
  if (const toml::array* a = r.array("lines")) {
    for (const auto& e : *a) {
      const auto name = e.value<std::string>();
      const auto dash = name ? name->find('-') : std::string::npos;
      const auto ok = [](const std::string& k) {
        return k == "C" || k == "A" || k == "G" || k == "B" || k == "F";
      };
      if (!name || dash == std::string::npos || !ok(name->substr(0, dash)) ||
          !ok(name->substr(dash + 1)) || name->substr(0, dash) == name->substr(dash + 1)) {
        r.fail(e, "lines",
               "expected \"P-Q\" with P and Q two of the block's points C, A, G, B, F "
               "(e.g. \"C-A\")");
      }
      p.lines.emplace_back(name->substr(0, dash), name->substr(dash + 1));
    }
  }
  if (p.wants(PostProduct::Lines) && p.lines.empty()) p.lines.emplace_back("C", "A");
  r.finish();
  return p;
}

/// [[section]]: a measuring line through a point (or a corner of the block), moved along the
/// bed by `along_bed`, normal to the bed unless a direction is given.
SectionSpec read_section(TableReader& r, const CaseSpec& c) {
  SectionSpec sec;
  sec.where = r.where();
  sec.name = r.string("name", "");
  if (sec.name.empty()) throw CaseError(r.where(), r.label() + " name is required");
  const auto point = r.point("point");
  const toml::node* at_node = r.get("at");
  if (point.has_value() == (at_node != nullptr)) {
    throw CaseError(r.where(), r.label() + ": give exactly one of point = [x, y] or at = \"C\"");
  }
  if (point) {
    sec.origin = *point;
  } else {
    if (!c.block) r.fail(*at_node, "at", "names a corner of the [block]: give a [block]");
    const BlockSpec& b = *c.block;
    const std::string at = r.choice("at", "C", {"C", "A", "G", "B", "F"});
    sec.origin = at == "C"   ? b.c
                 : at == "A" ? b.a
                 : at == "G" ? b.g
                 : at == "B" ? 0.5 * (b.c + b.a)
                             : 0.5 * (b.a + b.g);
  }
  const double along = r.number("along_bed", 0.0, -kInf, kInf);
  const auto dir = r.point("direction");
  if (!c.tank && (!dir || along != 0.0)) {
    throw CaseError(r.where(), r.label() + ": without a [tank] (whose bed gives the normal) " +
                                   "give direction = [dx, dy] and no along_bed");
  }
  if (c.tank) {
    const double alpha = c.tank->slope_deg * std::acos(-1.0) / 180.0;
    sec.origin += Vec2{std::cos(alpha), -std::sin(alpha)} * along;
    sec.direction = {std::sin(alpha), std::cos(alpha)};
  }
  if (dir) {
    if (!(norm(*dir) > 0.0)) r.fail_key("direction", "must not be zero");
    sec.direction = *dir * (1.0 / norm(*dir));
  }
  r.finish();
  for (const auto& other : c.sections) {
    if (other.name == sec.name) {
      r.fail_key("name", "\"" + sec.name + "\" is used by another section");
    }
  }
  return sec;
}

}  // namespace

CaseSpec parse_case_text(std::string_view text, const std::string& path) {
  CaseSpec c;
  c.file = {path, 0, 0};
  c.source_text = std::string(text);
  toml::table root_table;
  try {
    root_table = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw CaseError({path, e.source().begin.line, e.source().begin.column},
                    "syntax error: " + std::string(e.description()));
  }
  const toml::table empty;
  TableReader root(root_table, "case file", path);

  {
    TableReader r(section(root, "case", empty), "[case]", path);
    c.name = r.string("name", std::filesystem::path(path).stem().string());
    c.description = r.string("description", "");
    r.finish();
    if (c.name.empty()) throw CaseError(r.where(), "[case] name must not be empty");
  }
  {
    TableReader r(section(root, "particles", empty), "[particles]", path);
    c.dl = r.number("spacing", std::nullopt, 0.0, kInf, true);
    c.re_over_dl = r.number("kernel_radius", 3.5, 1.0, 8.0, true);
    c.lattice_origin = r.point("lattice_origin").value_or(Vec2{});
    c.wall_clearance = r.number("wall_clearance", c.wall_clearance, 0.0, 1.0);
    c.hydrostatic_start =
        r.choice("initial_state", "hydrostatic", {"hydrostatic", "lattice"}) == "hydrostatic";
    c.settle_time = r.number("settle_time", 0.0, 0.0, kInf);
    c.settle_damping = r.number("settle_damping", 0.1, 0.0, kInf, true);
    c.settle_courant = r.optional_number("settle_courant", 0.0, 1.0, true);
    r.finish();
  }
  {
    TableReader r(section(root, "physics", empty), "[physics]", path);
    c.density = r.number("density", 1000.0, 0.0, kInf, true);
    c.kinematic_viscosity = r.number("kinematic_viscosity", 1.0e-6, 0.0, kInf);
    c.gravity = r.point("gravity").value_or(Vec2{0.0, -9.81});
    c.sound_speed = r.optional_number("sound_speed", 0.0, kInf, true);
    c.sound_speed_factor = r.number("sound_speed_factor", 10.0, 0.0, kInf, true);
    c.eos_exponent = r.number("eos_exponent", 7.0, 1.0, 20.0);
    c.artificial_viscosity = r.number("artificial_viscosity", 0.02, 0.0, 1.0);
    c.surface_threshold = r.number("surface_threshold", 0.97, 0.0, 1.0, true, true);
    c.pressure_gradient = *scheme_from_key(kPressureGradientSchemes,
                                           r.choice("pressure_gradient", "suzuki2007-variational",
                                                    scheme_keys(kPressureGradientSchemes)));
    const auto walls = scheme_keys(kWallPressureSchemes);
    c.wall_pressure =
        *scheme_from_key(kWallPressureSchemes, r.choice("wall_pressure", walls.front(), walls));
    const auto collisions = scheme_keys(kWallCollisionSchemes);
    c.wall_collision = *scheme_from_key(kWallCollisionSchemes,
                                        r.choice("wall_collision", collisions.front(), collisions));
    c.collision_distance = r.number("collision_distance", 0.8, 0.5, 1.0, true, true);
    c.collision_restitution = r.number("collision_restitution", 0.2, 0.0, 1.0);
    // A scheme by its key; absent, the CaseSpec's default (`value` as constructed).
    const auto pick = [&](const auto& table, const std::string& key, auto value) {
      return *scheme_from_key(
          table, r.choice(key, std::string(scheme_key(table, value)), scheme_keys(table)));
    };
    c.particle_collision =
        pick(kParticleCollisionSchemes, "particle_collision", c.particle_collision);
    // Its constants, each an error without it (they would change nothing).
    const auto collision_constant = [&](const std::string& key, double lo, double hi,
                                        bool lo_open) {
      const auto value = r.optional_number(key, lo, hi, lo_open);
      if (value && c.particle_collision == ParticleCollisionScheme::None) {
        r.fail_key(key, "is a constant of particle_collision = \"jandaghian2021\" only");
      }
      return value;
    };
    if (const auto l0 = collision_constant("particle_collision_distance", 0.5, 1.0, true)) {
      c.particle_collision_distance = *l0;
    }
    if (const auto lambda = collision_constant("particle_collision_lambda", 0.0, 1.0, false)) {
      c.particle_collision_lambda = *lambda;
    }
    if (const auto e = collision_constant("particle_collision_restitution", 0.0, 1.0, false)) {
      c.particle_collision_restitution = *e;
    }
    if (const auto p_min =
            collision_constant("particle_collision_min_pressure", 0.0, kInf, false)) {
      c.particle_collision_min_pressure = *p_min;
    }
    c.negative_pressure = pick(kNegativePressureSchemes, "negative_pressure", c.negative_pressure);
    c.pressure_floor = r.number("pressure_floor", c.pressure_floor, -kInf, 0.0);
    c.wall_density = pick(kWallDensitySchemes, "wall_density", c.wall_density);
    c.artificial_viscosity_walls = pick(kArtificialViscosityWallsSchemes,
                                        "artificial_viscosity_walls", c.artificial_viscosity_walls);
    c.wall_friction = pick(kWallFrictionSchemes, "wall_friction", c.wall_friction);
    if (c.wall_friction != WallFrictionScheme::None && !(c.kinematic_viscosity > 0.0)) {
      r.fail_key("wall_friction",
                 "reads the law of the wall, whose stress needs the water's viscosity: give "
                 "kinematic_viscosity > 0");
    }
    c.side_wall_friction =
        pick(kSideWallFrictionSchemes, "side_wall_friction", c.side_wall_friction);
    if (const auto b = r.optional_number("flume_width", 0.0, kInf, true)) {
      if (c.side_wall_friction == SideWallFrictionScheme::None) {
        r.fail_key("flume_width",
                   "is the width between the side walls of side_wall_friction only: give "
                   "side_wall_friction = \"spalding1961\" or leave it out");
      }
      c.flume_width = *b;
    }
    if (c.side_wall_friction != SideWallFrictionScheme::None) {
      if (!(c.flume_width > 0.0)) {
        r.fail_key("side_wall_friction",
                   "needs the flume's width between its side walls: give flume_width (m)");
      }
      if (!(c.kinematic_viscosity > 0.0)) {
        r.fail_key("side_wall_friction",
                   "reads the law of the wall, whose stress needs the water's viscosity: give "
                   "kinematic_viscosity > 0");
      }
    }
    c.number_density = pick(kNumberDensitySchemes, "number_density", c.number_density);
    c.density_diffusion = r.number("density_diffusion", c.density_diffusion, 0.0, 1.0);
    c.density_diffusion_scheme =
        pick(kDensityDiffusionSchemes, "density_diffusion_scheme", c.density_diffusion_scheme);
    c.free_surface = pick(kFreeSurfaceSchemes, "free_surface", c.free_surface);
    c.shifting = pick(kShiftingSchemes, "shifting", c.shifting);
    c.shifting_in_continuity = r.boolean("shifting_in_continuity", c.shifting_in_continuity);
    c.surface_pressure_cap = r.boolean("surface_pressure_cap", c.surface_pressure_cap);
    // Its default applies where it can: with another gradient it is "none", and only an
    // explicit renormalisation there is an error.
    c.gradient_renormalisation = pick(kGradientRenormalisationSchemes, "gradient_renormalisation",
                                      renormalisation_in_effect(c));
    if (c.gradient_renormalisation != GradientRenormalisation::None &&
        c.pressure_gradient != PressureGradientScheme::Suzuki2007) {
      r.fail_key("gradient_renormalisation",
                 "renormalises the variational gradient only: it needs pressure_gradient = "
                 "\"suzuki2007-variational\"");
    }
    if (const auto tau = r.optional_number("strain_memory", 0.0, kInf, true)) {
      if (c.gradient_renormalisation != GradientRenormalisation::Strain) {
        r.fail_key("strain_memory",
                   "is the rest shape's memory of gradient_renormalisation = "
                   "\"khayyer2011-strain\" only");
      }
      c.strain_memory = *tau;
    }
    // Its default applies where it can: with the summed n or another gradient it is "summed",
    // and only an explicit "randles1996" there is an error.
    const bool rate_applies = c.number_density == NumberDensityScheme::Continuity &&
                              c.pressure_gradient == PressureGradientScheme::Suzuki2007;
    c.density_rate = pick(kDensityRateSchemes, "density_rate",
                          rate_applies ? c.density_rate : DensityRateScheme::Summed);
    if (c.density_rate != DensityRateScheme::Summed &&
        c.number_density != NumberDensityScheme::Continuity) {
      r.fail_key("density_rate",
                 "corrects the rate of an evolved number density only: it needs number_density = "
                 "\"continuity\"");
    }
    if (c.density_rate != DensityRateScheme::Summed &&
        c.pressure_gradient != PressureGradientScheme::Suzuki2007) {
      r.fail_key("density_rate",
                 "corrects the rate with its partner, the variational gradient: it needs "
                 "pressure_gradient = \"suzuki2007-variational\"");
    }
    r.finish();
  }
  {
    TableReader r(section(root, "time", empty), "[time]", path);
    c.end_time = r.number("end", std::nullopt, 0.0, kInf, true);
    c.step_mode = r.choice("step", "courant", {"courant", "fixed"}) == "fixed"
                      ? TimeStepMode::Fixed
                      : TimeStepMode::Courant;
    c.fixed_step = r.number("fixed_step", 2.5e-5, 0.0, kInf, true);
    c.courant = r.number("courant", 0.4, 0.0, 1.0, true);
    c.viscous_number = r.number("viscous_number", 0.125, 0.0, 0.5, true);
    if (c.step_mode == TimeStepMode::Fixed && c.fixed_step > c.end_time) {
      r.fail_key("fixed_step", "is longer than the end time");
    }
    r.finish();
  }
  {
    TableReader r(section(root, "output", empty), "[output]", path);
    c.output_interval = r.number("interval", 0.0, 0.0, kInf);
    if (const toml::array* a = r.array("times")) {
      for (const auto& e : *a) {
        const double t = r.number_value(e, "times", 0.0, c.end_time, false, false);
        if (!c.output_times.empty() && t <= c.output_times.back()) {
          r.fail(e, "times",
                 "must be increasing (" + fmt(t) + " after " + fmt(c.output_times.back()) + ")");
        }
        c.output_times.push_back(t);
      }
    }
    c.output_initial = r.boolean("initial", true);
    if (const toml::array* a = r.array("fields")) {
      for (const auto& e : *a) {
        const auto name = e.value<std::string>();
        const auto f = name ? find_field(*name) : std::nullopt;
        if (!f) {
          std::string list;
          for (const auto& k : kFields) list += (list.empty() ? "" : ", ") + std::string(k.name);
          r.fail(e, "fields",
                 "unknown field " + (name ? "\"" + *name + "\"" : type_name(e)) +
                     " (fields: " + list + ")");
        }
        c.output_fields.push_back(f->id);
      }
    } else {
      for (const auto& f : kFields) c.output_fields.push_back(f.id);
    }
    if (const toml::array* a = r.array("particles")) {
      for (const auto& e : *a) {
        const auto name = e.value<std::string>();
        const auto k = name ? kind_from_name(*name) : std::nullopt;
        if (!k) r.fail(e, "particles", "expected \"fluid\", \"wall\" or \"ghost\"");
        c.output_kinds.push_back(*k);
      }
    } else {
      c.output_kinds = {ParticleKind::Fluid, ParticleKind::Wall, ParticleKind::Ghost};
    }
    c.output_double_precision =
        r.choice("precision", "float32", {"float32", "float64"}) == "float64";
    r.finish();
  }
  {
    TableReader r(section(root, "checkpoint", empty), "[checkpoint]", path);
    c.checkpoint_interval = r.number("interval", 0.0, 0.0, kInf);
    c.checkpoint_wall_interval = r.number("wall_interval", 600.0, 0.0, kInf);
    c.checkpoint_keep = static_cast<int>(r.integer("keep", 2, 1, 1000));
    r.finish();
  }
  {
    TableReader r(section(root, "neighbours", empty), "[neighbours]", path);
    c.neighbour_skin = r.number("skin", 0.2, 0.0, 2.0, true);
    c.sort_interval = static_cast<int>(r.integer("sort_interval", 50, 0, 1000000));
    r.finish();
  }
  {
    TableReader r(section(root, "run", empty), "[run]", path);
    if (const toml::node* n = r.get("max_memory")) {
      std::optional<std::uint64_t> bytes;
      if (const auto given = n->value_exact<std::string>()) {
        bytes = parse_byte_size(*given);
      } else if (const auto v = n->value_exact<std::int64_t>(); v && *v > 0) {
        bytes = static_cast<std::uint64_t>(*v);
      }
      if (!bytes || *bytes == 0) {
        r.fail(*n, "max_memory",
               "expected a size such as \"6 GiB\" or \"500MB\", or a positive number of "
               "bytes");
      }
      c.max_memory = bytes;
    }
    r.finish();
  }
  {
    TableReader r(section(root, "stability", empty), "[stability]", path);
    c.max_density_ratio = r.number("max_density_ratio", 1.2, 1.0, kInf, true);
    const auto lo = r.point("domain_min");
    const auto hi = r.point("domain_max");
    if (lo.has_value() != hi.has_value()) {
      throw CaseError(r.where(), "[stability] give both domain_min and domain_max, or neither");
    }
    if (lo) {
      if (!(hi->x > lo->x && hi->y > lo->y)) {
        r.fail_key("domain_max", "must exceed domain_min in x and y");
      }
      c.domain = std::make_pair(*lo, *hi);
    }
    r.finish();
  }
  auto tables = [&](const std::string& key, auto&& read) {
    const toml::node* n = root.get(key);
    if (!n) return;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables()) {
      root.fail(*n, key, "expected tables [[" + key + "]]");
    }
    int k = 0;
    for (const auto& e : *a) {
      TableReader r(*e.as_table(), "[[" + key + "]] #" + std::to_string(++k), path);
      read(r);
    }
  };
  if (const toml::node* n = root.get("tank")) {
    if (!n->is_table()) root.fail(*n, "tank", "expected a table [tank]");
    TableReader r(*n->as_table(), "[tank]", path);
    read_tank(r, c);
  }
  if (const toml::node* n = root.get("block")) {
    if (!n->is_table()) root.fail(*n, "block", "expected a table [block]");
    TableReader r(*n->as_table(), "[block]", path);
    read_block(r, c);
  }
  tables("fluid", [&](TableReader& r) { c.fluids.push_back(read_fluid(r)); });
  tables("wall", [&](TableReader& r) { c.walls.push_back(read_wall(r)); });
  tables("section", [&](TableReader& r) { c.sections.push_back(read_section(r, c)); });
  if (const toml::node* n = root.get("gauges")) {
    if (!n->is_table()) root.fail(*n, "gauges", "expected a table [gauges]");
    TableReader r(*n->as_table(), "[gauges]", path);
    const toml::array* a = r.array("x");
    if (!a || a->empty()) throw CaseError(r.where(), "[gauges] x is required: the gauges' x (m)");
    for (const auto& e : *a)
      c.gauges.x.push_back(r.number_value(e, "x", -kInf, kInf, false, false));
    c.gauges.interval = r.number("interval", std::nullopt, 0.0, c.end_time, true);
    r.finish();
  }
  if (const toml::node* n = root.get("figures")) {
    if (!n->is_table()) root.fail(*n, "figures", "expected a table [figures]");
    TableReader r(*n->as_table(), "[figures]", path);
    const auto resolve = [&](const std::string& key) -> std::string {
      const std::string given = r.string(key, "");
      if (given.empty()) return given;
      const std::filesystem::path p(given);
      return p.is_absolute() ? given : (std::filesystem::path(path).parent_path() / p).string();
    };
    c.figures.measured_surface = resolve("measured_surface");
    c.figures.measured_profiles = resolve("measured_profiles");
    r.finish();
  }
  if (const toml::node* n = root.get("post")) {
    if (!n->is_table()) root.fail(*n, "post", "expected a table [post]");
    TableReader r(*n->as_table(), "[post]", path);
    c.post = read_post(r, c);
  }
  root.finish();

  if (c.fluids.empty()) throw CaseError(c.file, "the case has no [[fluid]] region or [tank]");
  if (c.walls.empty()) throw CaseError(c.file, "the case has no [[wall]] or [tank]");
  return c;
}

CaseSpec parse_case_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw CaseError({path, 0, 0}, "is a directory, not a case file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw CaseError({path, 0, 0},
                    std::string("cannot open case file: ") +
                        (std::filesystem::exists(path, ec) ? "permission denied" : "no such file"));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError({path, 0, 0}, "cannot read case file");
  return parse_case_text(text.str(), path);
}

}  // namespace wcmps
