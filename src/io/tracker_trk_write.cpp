// Writing Tracker projects (.trk XML, .trz zip): see tracker_trk.hpp.
#include "io/tracker_trk.hpp"

#include "io/text.hpp"
#include "io/zip_message.hpp"
#include "numerics/error.hpp"

#include <zip.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace tribolab::io {

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
  if (!std::is_sorted(spec.coords.begin(), spec.coords.end(),
                      [](const auto& a, const auto& b) { return a.frame < b.frame; })) {
    throw InputError("write_trk", "coordinate key frames must be sorted by frame");
  }
  int last_frame = spec.start_frame;
  for (const auto& t : tracks) {
    for (const auto& p : t.points) last_frame = std::max(last_frame, p.frame);
  }
  const int step_count = spec.step_count > 0 ? spec.step_count
                                             : (last_frame - spec.start_frame) / spec.step_size + 1;
  std::string video;
  if (!spec.video_path.empty()) {
    // Tracker 5's movie class; Tracker 6 loads it with its own movie engine
    video = "        <property name=\"video\" type=\"object\">\n"
            "        <object class=\"org.opensourcephysics.media.xuggle.XuggleVideo\">\n"
            "            <property name=\"path\" type=\"string\">" + xml_escape(spec.video_path) +
            "</property>\n        </object>\n        </property>\n";
  }
  if (spec.video_frame_count > 0) {
    video += "        <property name=\"video_framecount\" type=\"int\">" +
             std::to_string(spec.video_frame_count) + "</property>\n";
  }
  std::ostringstream o;
  const bool fixed = spec.coords.size() == 1;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<object class=\"org.opensourcephysics.cabrillo.tracker.TrackerPanel\">\n"
    << "    <property name=\"semantic_version\" type=\"string\">tribolab</property>\n"
    << "    <property name=\"videoclip\" type=\"object\">\n"
    << "    <object class=\"org.opensourcephysics.media.core.VideoClip\">\n"
    << video
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
      const auto [px, py] = world_to_image(coord_at(spec.coords, p.frame), p.x, p.y);
      // The reader refuses a mark beyond kMaxTrackCoordinate pixels, so the writer does too:
      // nothing is written that would not read back (a scale of 1e27 px per unit against 31
      // on the other axis turns a rounding of the world position into 1e11 px).
      if (!std::isfinite(px) || !std::isfinite(py)) {
        throw InputError("write_trk", "track '" + t.name + "' frame " + std::to_string(p.frame) +
                                          ": the position maps to no finite pixel");
      }
      if (std::abs(px) > kMaxTrackCoordinate || std::abs(py) > kMaxTrackCoordinate) {
        throw InputError("write_trk", "track '" + t.name + "' frame " + std::to_string(p.frame) +
                                          ": the position maps to pixel (" + format_number(px) + ", " +
                                          format_number(py) + "), beyond +-" + format_number(kMaxTrackCoordinate) +
                                          " px, which tribolab would refuse to read back");
      }
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

std::string write_trz(const std::string& trk_xml, const std::string& entry_name,
                      const std::vector<std::pair<std::string, std::string>>& files) {
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
  std::vector<std::pair<const std::string*, const std::string*>> all{{&entry_name, &trk_xml}};
  for (const auto& [name, bytes] : files) all.emplace_back(&name, &bytes);
  for (const auto& [name, bytes] : all) {
    zip_source_t* in = zip_source_buffer(z, bytes->data(), bytes->size(), 0);
    if (in == nullptr || zip_file_add(z, name->c_str(), in, ZIP_FL_OVERWRITE) < 0) {
      if (in) zip_source_free(in);
      zip_discard(z);
      zip_source_free(out);
      throw InputError("write_trz", "cannot add the entry '" + *name + "'");
    }
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
