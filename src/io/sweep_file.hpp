// The sweep file format (version 2): the CSV written by `bounce sweep`, its shards and its
// checkpoints. Line 1 is a header recording the format version, the shard, the grid, the
// fixed quantities, the output names and the physics:
//   # tribolab-sweep v2 | shard 0/1 | grid theta_deg=100:170:71 omega=30:50:21 |
//     fixed speed=4 mu=0.5 | outputs vx vy omega_out e contacts ... | model <description>
// (one line), line 2 the column names, then one line per cell of the shard in local order:
//   theta_deg,omega,<outputs>,<swept extras: speed, mu, ratio - those on the grid>
// Numbers are printed in the shortest form that reads back to the same double
// (std::to_chars), NaN as "nan", so equal results give byte-identical files.
// See docs/cli.md#bounce-sweep.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace tribolab::io {

/// Written by this version. v2 (whole-impact bounce cells) allows up to 16 outputs, v1 up to
/// 8; the grammar is the same, so v1 files are read too (and rewritten as v2 by a merge).
inline constexpr int kSweepFormatVersion = 2;
inline constexpr int kOldestSweepFormatVersion = 1;

struct SweepHeader {
  sweep::GridSpec grid;
  sweep::Shard shard;
  std::vector<std::string> outputs;  ///< output column names (vx, vy, omega_out, e, ...)
  std::string model;                 ///< the model's one-line description
  bool operator==(const SweepHeader&) const = default;
};

/// Shortest round-trip decimal form of v ("0.1", "1e-300", "-0"); NaN as "nan".
void append_number(std::string& out, double v);
std::string format_number_exact(double v);

/// The header line (with '\n') and the column-name line (with '\n').
std::string format_header(const SweepHeader& h);
std::string format_columns(const SweepHeader& h);
/// The header without its shard field: equal for the shards of one sweep.
std::string header_identity(const SweepHeader& h);
/// Parses a header line (without '\n'); throws InputError(where, ...) when malformed.
SweepHeader parse_header(std::string_view line, const std::string& where);

/// Appends the CSV lines of a chunk of results (see the file comment).
void append_cell_lines(std::string& out, const sweep::GridSpec& grid, const sweep::ChunkView& chunk);

/// Checks one data line against the expected cell (exact coordinate fields, field count,
/// outputs that parse as numbers); stores the outputs in `values` when not null. Throws
/// InputError(where, ...) on mismatch.
void check_cell_line(std::string_view line, const sweep::GridSpec& grid, const sweep::CellInput& cell,
                     std::size_t n_outputs, double* values, const std::string& where);

/// What a sweep file holds.
struct SweepFileScan {
  SweepHeader header;
  std::int64_t complete_cells = 0;  ///< verified complete data lines
  std::int64_t expected_cells = 0;  ///< cells of the header's shard
  std::uint64_t valid_bytes = 0;    ///< length of the prefix of complete lines
  bool torn_tail = false;           ///< a last line without '\n' (an interrupted write)
};

/// Reads and verifies a sweep file: header, column line and every complete data line
/// (coordinates must match the header's grid in order). A last line without '\n' is
/// reported as torn_tail, not an error. With `values`, the outputs of the complete lines
/// are stored (complete_cells x outputs). Throws InputError naming file:line.
SweepFileScan scan_sweep_file(const std::string& path, std::vector<double>* values = nullptr);

/// Called with each verified complete data line's local cell index and outputs.
using SweepCellVisitor = std::function<void(std::int64_t local, const std::vector<double>& outputs)>;
/// As above, streaming: each complete line's outputs go to `visit` as it is read, so a file of
/// any size is read in constant memory (the contour, thresholds and report of a big sweep).
SweepFileScan scan_sweep_file(const std::string& path, const SweepCellVisitor& visit);

}  // namespace tribolab::io
