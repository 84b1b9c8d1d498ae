#include "io/tracker_trk.hpp"

#include "io/text.hpp"
#include "io/zip_message.hpp"
#include "numerics/error.hpp"
#include "numerics/units.hpp"

#include <pugixml.hpp>
#include <zip.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

namespace tribolab::io {

namespace {

/// Largest .trk accepted from inside a zip (a zip bomb guard), bytes: the bound of a plain
/// .trk file (io::read_file).
constexpr std::uint64_t kMaxTrkBytes = kMaxTextInputBytes;

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
    if (!v) {
      const pugi::xml_node p = property(obj, name);
      fail(path + "/" + name, !p ? "missing element (a number is required here)"
                              : trim(p.child_value()).empty() ? "empty element (a number is required here)"
                                                              : "NaN where a number is required");
    }
    return *v;
  }

  std::optional<long long> opt_int(pugi::xml_node obj, const char* name, const std::string& path) {
    const auto v = opt_double(obj, name, path);
    if (!v) return std::nullopt;
    if (*v != std::floor(*v) || std::abs(*v) > kMaxFrameNumber) {
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
    if (n < 0 || n > kMaxFrameNumber) {
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

/// Resolves Tracker's "fixed" flags: a fixed origin, angle or scale takes the last saved
/// key frame's value at every frame, as Tracker's loader does.
struct Coords {
  bool fixed_origin = false, fixed_angle = false, fixed_scale = false;
  std::vector<TrkCoordFrame> keys;  // sorted by frame

  std::vector<TrkCoordFrame> resolved() const {
    std::vector<TrkCoordFrame> out = keys;
    const TrkCoordFrame& last = keys.back();
    for (TrkCoordFrame& c : out) {
      if (fixed_origin) {
        c.origin_x = last.origin_x;
        c.origin_y = last.origin_y;
      }
      if (fixed_angle) c.angle_deg = last.angle_deg;
      if (fixed_scale) {
        c.xscale = last.xscale;
        c.yscale = last.yscale;
      }
    }
    return out;
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
    c.keys.push_back(k);
  }
  if (c.keys.empty()) r.fail(base, "no key frame in the coordinate system");
  std::stable_sort(c.keys.begin(), c.keys.end(),
                   [](const auto& a, const auto& b) { return a.frame < b.frame; });
  return c;
}

TrkClip read_clip(Reader& r, pugi::xml_node panel) {
  TrkClip clip;
  const pugi::xml_node vc = object_of(property(panel, "videoclip"));
  if (vc) {
    const std::string p = "TrackerPanel/videoclip";
    const long long start = r.opt_int(vc, "startframe", p).value_or(0);
    const long long step = r.opt_int(vc, "stepsize", p).value_or(1);
    const long long count = r.opt_int(vc, "stepcount", p).value_or(0);
    clip.start_time_ms = r.opt_double(vc, "starttime", p).value_or(0);
    if (step < 1) r.fail(p + "/stepsize", "must be at least 1");
    if (start < 0) r.fail(p + "/startframe", "must not be negative");
    if (count < 0) r.fail(p + "/stepcount", "must not be negative");
    clip.start_frame = static_cast<int>(start);
    clip.step_size = static_cast<int>(step);
    clip.step_count = static_cast<int>(count);
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
  clip.frame_duration_ms = *dt;
  return clip;
}

}  // namespace

std::pair<double, double> image_to_world(const TrkCoordFrame& c, double px, double py) {
  const double u = (px - c.origin_x) / c.xscale;
  const double v = -(py - c.origin_y) / c.yscale;
  const double cs = std::cos(c.angle_deg * kRadPerDeg), sn = std::sin(c.angle_deg * kRadPerDeg);
  return {cs * u + sn * v, -sn * u + cs * v};
}

std::pair<double, double> world_to_image(const TrkCoordFrame& c, double x, double y) {
  const double cs = std::cos(c.angle_deg * kRadPerDeg), sn = std::sin(c.angle_deg * kRadPerDeg);
  const double u = cs * x - sn * y, v = sn * x + cs * y;
  return {c.origin_x + c.xscale * u, c.origin_y - c.yscale * v};
}

const TrkCoordFrame& coord_at(const std::vector<TrkCoordFrame>& keys, int frame) {
  TRIBOLAB_ASSERT(!keys.empty(), std::string("no coordinate key frame"));
  auto it = std::upper_bound(keys.begin(), keys.end(), frame,
                             [](int f, const TrkCoordFrame& k) { return f < k.frame; });
  return it == keys.begin() ? *it : *(it - 1);
}

bool TrkClip::on_step(long long frame) const {
  const long long rel = frame - start_frame;
  return rel >= 0 && rel % step_size == 0 && (step_count <= 0 || rel / step_size < step_count);
}

double TrkClip::t(long long frame) const {
  return (start_time_ms + static_cast<double>(frame - start_frame) * frame_duration_ms) / 1000;
}

TrkProject parse_trk_project(std::string_view xml, const std::string& source) {
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
  TrkProject project;
  project.source = source;
  if (const pugi::xml_node u = property(panel, "length_unit")) {
    const std::string unit(trim(u.child_value()));
    if (!unit.empty()) project.length_unit = unit;
  }
  project.coords = read_coords(r, panel).resolved();
  project.clip = read_clip(r, panel);
  if (const pugi::xml_node vc = object_of(property(panel, "videoclip"))) {
    if (const pugi::xml_node v = object_of(property(vc, "video"))) {
      project.video_path = std::string(trim(property(v, "path").child_value()));
    }
    const auto n = r.opt_int(vc, "video_framecount", "TrackerPanel/videoclip");
    project.video_frame_count = static_cast<int>(std::max(0LL, n.value_or(0)));
  }
  const TrkClip& clip = project.clip;
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
    if (auto e = name_text_problem(tr.name); !e.empty()) r.fail(base + "/name", "the track name " + e);
    const std::string path = base + "(" + tr.name + ")/framedata";
    const pugi::xml_node fd = property(obj, "framedata");
    std::size_t dropped = 0;
    std::map<long long, std::pair<double, double>> marks;
    for (pugi::xml_node entry : fd.children("property")) {
      const long long n = r.index_of(entry, path);
      const std::string p = path + "/[" + std::to_string(n) + "]";
      const pugi::xml_node f = object_of(entry);
      if (!f) r.fail(p, "missing element object");
      const std::pair<double, double> xy{check_track_value(r.req_double(f, "x", p), kMaxTrackCoordinate, r.source() + ": " + p, "x (px)"),
                                         check_track_value(r.req_double(f, "y", p), kMaxTrackCoordinate, r.source() + ": " + p, "y (px)")};
      if (!marks.emplace(n, xy).second) r.fail(p, "frame " + std::to_string(n) + " is marked twice in this track");
    }
    for (const auto& [n, px] : marks) {
      if (!clip.on_step(n)) {
        ++dropped;
        continue;
      }
      track::TrackPoint p;
      p.frame = static_cast<int>(n);
      p.t = clip.t(n);
      p.x = px.first;
      p.y = px.second;
      tr.points.push_back(p);
    }
    if (dropped > 0) {
      project.warnings.push_back("track '" + tr.name + "': " + std::to_string(dropped) +
                                 " point(s) outside the video clip's steps were left out, as in "
                                 "Tracker's table");
    }
    project.marks_px.push_back(std::move(tr));
  }
  if (project.marks_px.empty()) r.fail("TrackerPanel/tracks", "no PointMass track in the file");
  return project;
}

namespace {

track::TrackSet to_world(TrkProject project) {
  track::TrackSet set;
  set.source = project.source;
  set.format = "trk";
  set.file_length_unit = project.length_unit;
  set.warnings = std::move(project.warnings);
  for (track::Track& tr : project.marks_px) {
    for (track::TrackPoint& p : tr.points) {
      const auto [x, y] = image_to_world(coord_at(project.coords, p.frame), p.x, p.y);
      p.x = x;
      p.y = y;
    }
    set.tracks.push_back(std::move(tr));
  }
  return set;
}

}  // namespace

track::TrackSet parse_trk(std::string_view xml, const std::string& source) {
  return to_world(parse_trk_project(xml, source));
}

namespace {

struct ZipCloser {
  void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileCloser {
  void operator()(zip_file_t* f) const { zip_fclose(f); }
};


/// The .trk chosen in an open archive: its XML, its entry name and every entry's name.
struct TrkInZip {
  std::string xml, entry;
  std::vector<std::string> entries;
};

/// Streams entry `index` of `z` to `sink` in chunks: memory grows with the data actually
/// inflated, never with the size the archive claims, and stops at `max_bytes` (a zip bomb
/// guard).
template <class Sink>
void read_entry(zip_t* z, zip_uint64_t index, const std::string& where, std::uint64_t max_bytes,
                Sink&& sink, const std::string& why = "") {
  std::unique_ptr<zip_file_t, ZipFileCloser> f(zip_fopen_index(z, index, 0));
  if (!f) throw InputError(where, std::string("cannot open entry: ") + zip_strerror(z));
  std::vector<char> chunk(1 << 16);
  std::uint64_t total = 0;
  while (true) {
    const zip_int64_t k = zip_fread(f.get(), chunk.data(), chunk.size());
    if (k < 0) throw InputError(where, std::string("corrupt entry: ") + zip_file_strerror(f.get()));
    if (k == 0) break;
    total += static_cast<std::uint64_t>(k);
    if (total > max_bytes) {
      throw InputError(where, "entry too large (over " + std::to_string(max_bytes >> 20) + " MB" + why + ")");
    }
    sink(chunk.data(), static_cast<std::size_t>(k));
  }
}

TrkInZip trk_in_zip(zip_t* z, const std::string& source, const std::string& entry) {
  TrkInZip out;
  const zip_int64_t count = zip_get_num_entries(z, 0);
  std::vector<std::string> trks;
  zip_int64_t chosen = -1;
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(z, static_cast<zip_uint64_t>(i), 0);
    if (name == nullptr) continue;
    out.entries.emplace_back(name);
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
  out.entry = zip_get_name(z, static_cast<zip_uint64_t>(chosen), 0);
  read_entry(z, static_cast<zip_uint64_t>(chosen), source + ":" + out.entry, kMaxTrkBytes,
             [&](const char* d, std::size_t n) { out.xml.append(d, n); });
  return out;
}

std::unique_ptr<zip_t, ZipCloser> open_zip_file(const std::string& path) {
  int code = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_RDONLY, &code);
  if (z == nullptr) {
    zip_error_t err;
    zip_error_init_with_code(&err, code);
    throw InputError(path, "not a readable .trz/zip archive: " + zip_message(&err));
  }
  return std::unique_ptr<zip_t, ZipCloser>(z);
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
  const TrkInZip trk = trk_in_zip(z.get(), source, entry);
  track::TrackSet set = parse_trk(trk.xml, source + ":" + trk.entry);
  set.format = "trz";
  return set;
}

TrzContents read_trz_file(const std::string& path, const std::string& entry) {
  const auto z = open_zip_file(path);
  TrkInZip trk = trk_in_zip(z.get(), path, entry);
  TrzContents out;
  out.project = parse_trk_project(trk.xml, path + ":" + trk.entry);
  out.trk_entry = std::move(trk.entry);
  out.entries = std::move(trk.entries);
  return out;
}

void extract_zip_entry(const std::string& zip_path, const std::string& entry,
                       const std::string& out_path, std::uint64_t max_bytes) {
  const auto z = open_zip_file(zip_path);
  const std::string where = zip_path + ":" + entry;
  const zip_int64_t index = zip_name_locate(z.get(), entry.c_str(), 0);
  if (index < 0) throw InputError(where, "no such entry in the archive");
  // A video is already compressed: deflate gains ~1 % on the Tracker projects we have
  // (mp4 entries 199 KB -> 198 KB, 3.7 MB -> 3.7 MB). An entry inflating to more than
  // kMaxInflation times its compressed bytes (plus 16 MiB of slack for small or raw clips)
  // is not a video tribolab can use but a zip bomb: a 6 MB archive wrote 6 GB to $TMPDIR.
  constexpr std::uint64_t kMaxInflation = 100, kSlack = 16ull << 20;
  zip_stat_t st;
  zip_stat_init(&st);
  if (zip_stat_index(z.get(), static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_COMP_SIZE)) {
    throw InputError(where, std::string("cannot read the entry's size: ") + zip_strerror(z.get()));
  }
  const std::uint64_t bound = std::min(max_bytes, kSlack + kMaxInflation * st.comp_size);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::fopen(out_path.c_str(), "wb"), &std::fclose);
  if (!out) throw InputError(out_path, "cannot create the file");
  read_entry(z.get(), static_cast<zip_uint64_t>(index), where, bound,
             [&](const char* d, std::size_t n) {
               if (std::fwrite(d, 1, n, out.get()) != n) {
                 throw InputError(out_path, "cannot write (disk full?)");
               }
             },
             bound < max_bytes ? ", " + std::to_string(kMaxInflation) + " times its " +
                                     std::to_string(st.comp_size) +
                                     " compressed bytes: a video inflates ~1x; a zip bomb?"
                               : std::string());
  if (std::fflush(out.get()) != 0) throw InputError(out_path, "cannot write (disk full?)");
}

}  // namespace tribolab::io
