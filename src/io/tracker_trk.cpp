#include "io/tracker_trk.hpp"

#include "io/text.hpp"
#include "numerics/error.hpp"

#include <pugixml.hpp>
#include <zip.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

namespace tribolab::io {

namespace {

constexpr double kDegree = std::numbers::pi / 180;
/// Frames beyond this are refused: no video has them, and they would overflow int arithmetic.
constexpr long long kMaxFrame = 100'000'000;
/// Largest .trk accepted from inside a zip (a zip bomb guard), bytes.
constexpr std::size_t kMaxTrkBytes = 512u << 20;

bool ends_with(std::string_view s, std::string_view p) {
  return s.size() >= p.size() && s.substr(s.size() - p.size()) == p;
}

std::string short_class(std::string_view cls) {
  const auto dot = cls.find_last_of(".$");
  return std::string(dot == std::string_view::npos ? cls : cls.substr(dot + 1));
}

/// The <property name="..."> child of an <object> element.
pugi::xml_node property(pugi::xml_node object, const char* name) {
  for (pugi::xml_node p : object.children("property")) {
    if (std::string_view(p.attribute("name").value()) == name) return p;
  }
  return {};
}

/// The <object> held by a property of type "object" (or the property itself if none).
pugi::xml_node object_of(pugi::xml_node prop) { return prop.child("object"); }

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
    throw InputError(source_ + ": " + path, msg);
  }

  std::optional<double> opt_double(pugi::xml_node obj, const char* name, const std::string& path) {
    const pugi::xml_node p = property(obj, name);
    if (!p) return std::nullopt;
    const std::string_view text = trim(p.child_value());
    if (text == "NaN" || text.empty()) return std::nullopt;
    return parse_double(text, source_ + ": " + path + "/" + name, true);
  }

  double req_double(pugi::xml_node obj, const char* name, const std::string& path) {
    const auto v = opt_double(obj, name, path);
    if (!v) fail(path + "/" + name, "missing element (a number is required here)");
    return *v;
  }

  std::optional<long long> opt_int(pugi::xml_node obj, const char* name, const std::string& path) {
    const auto v = opt_double(obj, name, path);
    if (!v) return std::nullopt;
    if (*v != std::floor(*v) || std::abs(*v) > kMaxFrame) {
      fail(path + "/" + name, "expected a whole number of frames up to 1e8, got " + format_number(*v));
    }
    return static_cast<long long>(*v);
  }

  /// The index n of an array entry named "[n]".
  long long index_of(pugi::xml_node entry, const std::string& path) {
    const std::string_view name = entry.attribute("name").value();
    long long n = -1;
    if (name.size() >= 3 && name.front() == '[' && name.back() == ']') {
      const auto [ptr, ec] = std::from_chars(name.data() + 1, name.data() + name.size() - 1, n);
      if (ec != std::errc() || ptr != name.data() + name.size() - 1) n = -1;
    }
    if (n < 0 || n > kMaxFrame) {
      fail(path + "/" + std::string(name.substr(0, 30)),
           "expected an array entry \"[n]\" with 0 <= n <= 1e8");
    }
    return n;
  }

  const std::string& source() const { return source_; }

 private:
  std::string source_;
};

/// The TrackerPanel object: the root, or the first descendant of that class (iterative walk,
/// so deeply nested input cannot exhaust the stack).
pugi::xml_node find_panel(const pugi::xml_document& doc) {
  std::vector<pugi::xml_node> stack{doc};
  while (!stack.empty()) {
    const pugi::xml_node n = stack.back();
    stack.pop_back();
    if (std::string_view(n.name()) == "object" &&
        ends_with(n.attribute("class").value(), "TrackerPanel")) {
      return n;
    }
    std::vector<pugi::xml_node> kids;
    for (pugi::xml_node c : n.children()) {
      if (c.type() == pugi::node_element) kids.push_back(c);
    }
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return {};
}

struct Clip {
  long long start_frame = 0, step_size = 1;
  std::optional<long long> step_count;
  double start_time_ms = 0, frame_ms = 0;
};

struct Coords {
  bool fixed_origin = false, fixed_angle = false, fixed_scale = false;
  std::vector<std::pair<long long, TrkCoordFrame>> keys;  // sorted by frame

  TrkCoordFrame at(long long frame) const {
    // key frame in force: the last one at or before `frame` (the first before any key)
    auto it = std::upper_bound(keys.begin(), keys.end(), frame,
                               [](long long f, const auto& k) { return f < k.first; });
    if (it != keys.begin()) --it;
    TrkCoordFrame c = it->second;
    const TrkCoordFrame& last = keys.back().second;
    if (fixed_origin) {
      c.origin_x = last.origin_x;
      c.origin_y = last.origin_y;
    }
    if (fixed_angle) c.angle_deg = last.angle_deg;
    if (fixed_scale) {
      c.xscale = last.xscale;
      c.yscale = last.yscale;
    }
    return c;
  }
};

bool read_bool(pugi::xml_node obj, const char* name) {
  return std::string_view(trim(property(obj, name).child_value())) == "true";
}

Coords read_coords(Reader& r, pugi::xml_node panel) {
  const pugi::xml_node obj = object_of(property(panel, "coords"));
  if (!obj) r.fail("TrackerPanel/coords", "missing element (the image coordinate system)");
  Coords c;
  c.fixed_origin = read_bool(obj, "fixedorigin");
  c.fixed_angle = read_bool(obj, "fixedangle");
  c.fixed_scale = read_bool(obj, "fixedscale");
  const std::string base = "TrackerPanel/coords/framedata";
  const pugi::xml_node fd = property(obj, "framedata");
  if (!fd) r.fail(base, "missing element (the coordinate system's key frames)");
  for (pugi::xml_node entry : fd.children("property")) {
    const long long n = r.index_of(entry, base);
    const std::string path = base + "/[" + std::to_string(n) + "]";
    const pugi::xml_node f = object_of(entry);
    if (!f) r.fail(path, "missing element object");
    TrkCoordFrame k;
    k.frame = static_cast<int>(n);
    k.origin_x = r.req_double(f, "xorigin", path);
    k.origin_y = r.req_double(f, "yorigin", path);
    k.angle_deg = r.req_double(f, "angle", path);
    k.xscale = r.req_double(f, "xscale", path);
    k.yscale = r.req_double(f, "yscale", path);
    if (!(k.xscale > 0) || !(k.yscale > 0)) {
      r.fail(path, "xscale and yscale must be positive (pixels per unit), got " +
                       format_number(k.xscale) + " and " + format_number(k.yscale));
    }
    c.keys.emplace_back(n, k);
  }
  if (c.keys.empty()) r.fail(base, "no key frame in the coordinate system");
  std::stable_sort(c.keys.begin(), c.keys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return c;
}

Clip read_clip(Reader& r, pugi::xml_node panel) {
  Clip clip;
  const pugi::xml_node vc = object_of(property(panel, "videoclip"));
  if (vc) {
    const std::string p = "TrackerPanel/videoclip";
    clip.start_frame = r.opt_int(vc, "startframe", p).value_or(0);
    clip.step_size = r.opt_int(vc, "stepsize", p).value_or(1);
    clip.step_count = r.opt_int(vc, "stepcount", p);
    clip.start_time_ms = r.opt_double(vc, "starttime", p).value_or(0);
    if (clip.step_size < 1) r.fail(p + "/stepsize", "must be at least 1");
    if (clip.start_frame < 0) r.fail(p + "/startframe", "must not be negative");
  }
  std::optional<double> dt;
  if (const pugi::xml_node cc = object_of(property(panel, "clipcontrol"))) {
    dt = r.opt_double(cc, "delta_t", "TrackerPanel/clipcontrol");
  }
  if (!dt && vc) {  // image videos keep their own frame duration
    if (const pugi::xml_node v = object_of(property(vc, "video"))) {
      dt = r.opt_double(v, "delta_t", "TrackerPanel/videoclip/video");
    }
  }
  if (!dt) r.fail("TrackerPanel/clipcontrol/delta_t", "missing element (the frame duration in ms)");
  if (!(*dt > 0)) {
    r.fail("TrackerPanel/clipcontrol/delta_t", "frame duration must be positive, got " +
                                                   format_number(*dt) + " ms");
  }
  clip.frame_ms = *dt;
  return clip;
}

}  // namespace

std::pair<double, double> image_to_world(const TrkCoordFrame& c, double px, double py) {
  const double u = (px - c.origin_x) / c.xscale;
  const double v = -(py - c.origin_y) / c.yscale;
  const double cs = std::cos(c.angle_deg * kDegree), sn = std::sin(c.angle_deg * kDegree);
  return {cs * u + sn * v, -sn * u + cs * v};
}

std::pair<double, double> world_to_image(const TrkCoordFrame& c, double x, double y) {
  const double cs = std::cos(c.angle_deg * kDegree), sn = std::sin(c.angle_deg * kDegree);
  const double u = cs * x - sn * y, v = sn * x + cs * y;
  return {c.origin_x + c.xscale * u, c.origin_y - c.yscale * v};
}

track::TrackSet parse_trk(std::string_view xml, const std::string& source) {
  Reader r(source);
  pugi::xml_document doc;
  const pugi::xml_parse_result ok =
      doc.load_buffer(xml.data(), xml.size(), pugi::parse_default, pugi::encoding_auto);
  if (!ok) {
    const std::size_t off = std::min<std::size_t>(static_cast<std::size_t>(std::max<std::ptrdiff_t>(ok.offset, 0)), xml.size());
    const long line = 1 + std::count(xml.begin(), xml.begin() + static_cast<std::ptrdiff_t>(off), '\n');
    throw InputError(source + ":" + std::to_string(line),
                     std::string("malformed XML: ") + ok.description());
  }
  const pugi::xml_node panel = find_panel(doc);
  if (!panel) {
    r.fail("TrackerPanel", "missing element: no <object class=\"...TrackerPanel\"> (not a Tracker file?)");
  }
  track::TrackSet set;
  set.source = source;
  set.format = "trk";
  if (const pugi::xml_node u = property(panel, "length_unit")) {
    const std::string unit(trim(u.child_value()));
    if (!unit.empty()) set.file_length_unit = unit;
  }
  const Coords coords = read_coords(r, panel);
  const Clip clip = read_clip(r, panel);
  const pugi::xml_node tracks = property(panel, "tracks");
  if (!tracks) r.fail("TrackerPanel/tracks", "missing element (the list of tracks)");
  int item = 0;
  for (pugi::xml_node it : tracks.children("property")) {
    const pugi::xml_node obj = object_of(it);
    const std::string cls = short_class(obj.attribute("class").value());
    const std::string base = "TrackerPanel/tracks/item[" + std::to_string(item++) + "]";
    if (cls != "PointMass") continue;  // axes, tapes, protractors, models: not marked data
    track::Track tr;
    tr.name = std::string(trim(property(obj, "name").child_value()));
    if (tr.name.empty()) tr.name = "track " + std::to_string(item);
    const std::string path = base + "(" + tr.name + ")/framedata";
    const pugi::xml_node fd = property(obj, "framedata");
    std::size_t dropped = 0;
    std::map<long long, std::pair<double, double>> marks;
    for (pugi::xml_node entry : fd.children("property")) {
      const long long n = r.index_of(entry, path);
      const std::string p = path + "/[" + std::to_string(n) + "]";
      const pugi::xml_node f = object_of(entry);
      if (!f) r.fail(p, "missing element object");
      marks[n] = {r.req_double(f, "x", p), r.req_double(f, "y", p)};
    }
    for (const auto& [n, px] : marks) {
      const long long rel = n - clip.start_frame;
      if (rel < 0 || rel % clip.step_size != 0 ||
          (clip.step_count && rel / clip.step_size >= *clip.step_count)) {
        ++dropped;
        continue;
      }
      const auto [x, y] = image_to_world(coords.at(n), px.first, px.second);
      track::TrackPoint p;
      p.frame = static_cast<int>(n);
      p.t = (clip.start_time_ms + static_cast<double>(rel) * clip.frame_ms) / 1000;
      p.x = x;
      p.y = y;
      tr.points.push_back(p);
    }
    if (dropped > 0) {
      set.warnings.push_back("track '" + tr.name + "': " + std::to_string(dropped) +
                             " point(s) outside the video clip's steps were left out, as in "
                             "Tracker's table");
    }
    set.tracks.push_back(std::move(tr));
  }
  if (set.tracks.empty()) r.fail("TrackerPanel/tracks", "no PointMass track in the file");
  return set;
}

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};

std::string zip_message(zip_error_t* e) {
  std::string m = zip_error_strerror(e);
  zip_error_fini(e);
  return m;
}

}  // namespace

track::TrackSet read_trz(std::string_view zip_bytes, const std::string& source,
                         const std::string& entry) {
  zip_error_t err;
  zip_error_init(&err);
  zip_source_t* src = zip_source_buffer_create(zip_bytes.data(), zip_bytes.size(), 0, &err);
  if (src == nullptr) throw InputError(source, "cannot read the zip archive: " + zip_message(&err));
  std::unique_ptr<zip_t, ZipCloser> z(zip_open_from_source(src, ZIP_RDONLY, &err));
  if (!z) {
    zip_source_free(src);
    throw InputError(source, "not a valid .trz/zip archive: " + zip_message(&err));
  }
  zip_error_fini(&err);
  const zip_int64_t count = zip_get_num_entries(z.get(), 0);
  std::vector<std::string> trks;
  zip_int64_t chosen = -1;
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(z.get(), static_cast<zip_uint64_t>(i), 0);
    if (name == nullptr) continue;
    std::string lname(name);
    for (char& c : lname) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!ends_with(lname, ".trk")) continue;
    trks.emplace_back(name);
    if (chosen < 0 && (entry.empty() || entry == name)) chosen = i;
  }
  if (trks.empty()) throw InputError(source, "the archive holds no .trk file");
  if (chosen < 0) {
    std::string list;
    for (const auto& t : trks) list += (list.empty() ? "'" : ", '") + t + "'";
    throw InputError(source, "no entry '" + entry + "' in the archive; its .trk files: " + list);
  }
  const std::string inner = source + ":" + zip_get_name(z.get(), static_cast<zip_uint64_t>(chosen), 0);
  std::unique_ptr<zip_file_t, ZipFileCloser> f(zip_fopen_index(z.get(), static_cast<zip_uint64_t>(chosen), 0));
  if (!f) throw InputError(inner, std::string("cannot open entry: ") + zip_strerror(z.get()));
  // read in chunks: memory grows with the data actually inflated, never with the size the
  // archive claims, and stops at kMaxTrkBytes (a zip bomb guard)
  std::string xml;
  std::vector<char> chunk(1 << 16);
  while (true) {
    const zip_int64_t k = zip_fread(f.get(), chunk.data(), chunk.size());
    if (k < 0) throw InputError(inner, std::string("corrupt entry: ") + zip_file_strerror(f.get()));
    if (k == 0) break;
    if (xml.size() + static_cast<std::size_t>(k) > kMaxTrkBytes) {
      throw InputError(inner, "entry too large (over 512 MB)");
    }
    xml.append(chunk.data(), static_cast<std::size_t>(k));
  }
  track::TrackSet set = parse_trk(xml, inner);
  set.format = "trz";
  return set;
}

namespace {

std::string num(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string s(buf, ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // Java writes 66.0
  return s;
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

}  // namespace

std::string write_trk(const std::vector<track::Track>& tracks, const TrkWriteSpec& spec) {
  if (spec.coords.empty() || spec.coords.front().frame != 0) {
    throw InputError("write_trk", "the first coordinate key frame must be frame 0");
  }
  int last_frame = spec.start_frame;
  for (const auto& t : tracks) {
    for (const auto& p : t.points) last_frame = std::max(last_frame, p.frame);
  }
  const int step_count = spec.step_count > 0 ? spec.step_count
                                             : (last_frame - spec.start_frame) / spec.step_size + 1;
  std::ostringstream o;
  const bool fixed = spec.coords.size() == 1;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">\n"
    << "    <property name=\"semantic_version\" type=\"string\">tribolab</property>\n"
    << "    <property name=\"videoclip\" type=\"object\">\n"
    << "    <object class=\"org.opensourcephysics.media.core.VideoClip\">\n"
    << "        <property name=\"startframe\" type=\"int\">" << spec.start_frame << "</property>\n"
    << "        <property name=\"stepsize\" type=\"int\">" << spec.step_size << "</property>\n"
    << "        <property name=\"stepcount\" type=\"int\">" << step_count << "</property>\n"
    << "        <property name=\"starttime\" type=\"double\">" << num(spec.start_time_ms) << "</property>\n"
    << "    </object>\n    </property>\n"
    << "    <property name=\"clipcontrol\" type=\"object\">\n"
    << "    <object class=\"org.opensourcephysics.media.core.StepperClipControl\">\n"
    << "        <property name=\"rate\" type=\"double\">1.0</property>\n"
    << "        <property name=\"delta_t\" type=\"double\">" << num(spec.frame_duration_ms) << "</property>\n"
    << "        <property name=\"frame\" type=\"int\">0</property>\n"
    << "    </object>\n    </property>\n"
    << "    <property name=\"coords\" type=\"object\">\n"
    << "    <object class=\"org.opensourcephysics.media.core.ImageCoordSystem\">\n";
  for (const char* f : {"fixedorigin", "fixedangle", "fixedscale"}) {
    o << "        <property name=\"" << f << "\" type=\"boolean\">" << (fixed ? "true" : "false")
      << "</property>\n";
  }
  o << "        <property name=\"locked\" type=\"boolean\">false</property>\n"
    << "        <property name=\"framedata\" type=\"array\" "
       "class=\"[Lorg.opensourcephysics.media.core.ImageCoordSystem$FrameData;\">\n";
  for (const TrkCoordFrame& c : spec.coords) {
    o << "            <property name=\"[" << c.frame << "]\" type=\"object\">\n"
      << "            <object class=\"org.opensourcephysics.media.core.ImageCoordSystem$FrameData\">\n"
      << "                <property name=\"xorigin\" type=\"double\">" << num(c.origin_x) << "</property>\n"
      << "                <property name=\"yorigin\" type=\"double\">" << num(c.origin_y) << "</property>\n"
      << "                <property name=\"angle\" type=\"double\">" << num(c.angle_deg) << "</property>\n"
      << "                <property name=\"xscale\" type=\"double\">" << num(c.xscale) << "</property>\n"
      << "                <property name=\"yscale\" type=\"double\">" << num(c.yscale) << "</property>\n"
      << "            </object>\n            </property>\n";
  }
  o << "        </property>\n    </object>\n    </property>\n"
    << "    <property name=\"length_unit\" type=\"string\">" << xml_escape(spec.length_unit)
    << "</property>\n"
    << "    <property name=\"tracks\" type=\"collection\" class=\"java.util.ArrayList\">\n";
  for (const auto& t : tracks) {
    o << "        <property name=\"item\" type=\"object\">\n"
      << "        <object class=\"org.opensourcephysics.cabrillo.tracker.PointMass\">\n"
      << "            <property name=\"mass\" type=\"double\">1.0</property>\n"
      << "            <property name=\"name\" type=\"string\">" << xml_escape(t.name) << "</property>\n"
      << "            <property name=\"framedata\" type=\"array\" "
         "class=\"[Lorg.opensourcephysics.cabrillo.tracker.PointMass$FrameData;\">\n";
    for (const auto& p : t.points) {
      // key frame in force at this frame
      TrkCoordFrame c = spec.coords.front();
      for (const auto& k : spec.coords) {
        if (k.frame <= p.frame) c = k;
      }
      const auto [px, py] = world_to_image(c, p.x, p.y);
      o << "                <property name=\"[" << p.frame << "]\" type=\"object\">\n"
        << "                <object class=\"org.opensourcephysics.cabrillo.tracker.PointMass$FrameData\">\n"
        << "                    <property name=\"x\" type=\"double\">" << num(px) << "</property>\n"
        << "                    <property name=\"y\" type=\"double\">" << num(py) << "</property>\n"
        << "                </object>\n                </property>\n";
    }
    o << "            </property>\n        </object>\n        </property>\n";
  }
  o << "    </property>\n</object>\n";
  return o.str();
}

std::string write_trz(const std::string& trk_xml, const std::string& entry_name) {
  zip_error_t err;
  zip_error_init(&err);
  zip_source_t* out = zip_source_buffer_create(nullptr, 0, 0, &err);
  if (out == nullptr) throw InputError("write_trz", zip_message(&err));
  zip_source_keep(out);
  zip_t* z = zip_open_from_source(out, ZIP_TRUNCATE, &err);
  if (z == nullptr) {
    zip_source_free(out);
    throw InputError("write_trz", zip_message(&err));
  }
  zip_source_t* in = zip_source_buffer(z, trk_xml.data(), trk_xml.size(), 0);
  if (in == nullptr || zip_file_add(z, entry_name.c_str(), in, ZIP_FL_OVERWRITE) < 0) {
    if (in) zip_source_free(in);
    zip_discard(z);
    zip_source_free(out);
    throw InputError("write_trz", "cannot add the entry");
  }
  if (zip_close(z) != 0) {
    zip_discard(z);
    zip_source_free(out);
    throw InputError("write_trz", "cannot finish the archive");
  }
  std::string bytes;
  if (zip_source_open(out) == 0) {
    zip_source_seek(out, 0, SEEK_END);
    const zip_int64_t size = zip_source_tell(out);
    zip_source_seek(out, 0, SEEK_SET);
    bytes.resize(static_cast<std::size_t>(std::max<zip_int64_t>(size, 0)));
    const zip_int64_t got = zip_source_read(out, bytes.data(), bytes.size());
    zip_source_close(out);
    if (got != size) bytes.clear();
  }
  zip_source_free(out);
  if (bytes.empty()) throw InputError("write_trz", "cannot read back the archive");
  return bytes;
}

}  // namespace tribolab::io
