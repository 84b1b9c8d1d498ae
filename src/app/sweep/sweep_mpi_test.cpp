// Run by CTest under `mpirun -np 2` (test sweep_mpi_2ranks, built with -DTRIBOLAB_MPI=ON);
// skipped when the test program is started without an MPI launcher.
#include "app/sweep/sweep_mpi.hpp"

#include <gtest/gtest.h>

#if TRIBOLAB_WITH_MPI
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/text.hpp"
#include "numerics/error.hpp"
#include "sweep/synthetic.hpp"

namespace tribolab::app {
using namespace ::tribolab::io;
namespace {

namespace fs = std::filesystem;

MpiSession& session() {
  static MpiSession s;  // finalised at exit
  return s;
}

/// A directory chosen by rank 0 and known to all ranks.
std::string shared_dir(const std::string& name) {
  std::string dir;
  if (session().rank() == 0) {
    dir = (fs::temp_directory_path() / ("tribolab_mpi_" + name + "_" + std::to_string(::getpid()))).string();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  long long n = static_cast<long long>(dir.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  dir.resize(static_cast<std::size_t>(n));
  MPI_Bcast(dir.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
  return dir;
}

SweepCommandOptions mpi_options_for(const std::string& out) {
  SweepCommandOptions o;
  o.grid.axes = {sweep::Axis{sweep::Quantity::mu, 0.3, 0.7, 2},
                 sweep::Axis{sweep::Quantity::theta_deg, 100, 170, 29},
                 sweep::Axis{sweep::Quantity::omega, 30, 50, 17}};
  o.out = out;
  o.threads = 2;
  o.chunk_cells = 3;  // rounds of 3 x 4 x 2 x ranks cells: many rounds
  return o;
}

TEST(SweepMpi, RanksWriteTheSameBytesAsOneProcessAndResume) {
  if (!launched_by_mpi_launcher()) GTEST_SKIP() << "needs mpirun: ctest -R sweep_mpi_2ranks";
  const int rank = session().rank();
  const std::string dir = shared_dir("bytes");
  const sweep::CellModel model = sweep::synthetic::wave_model();
  std::string reference;
  if (rank == 0) {
    SweepCommandOptions o = mpi_options_for(dir + "/one.csv");
    o.contour_out = dir + "/one_contour.csv";
    run_sweep_command(o, model, nullptr);
    reference = read_file(o.out);
  }
  // Whole sweep over the ranks, with the derived maps.
  SweepCommandOptions o = mpi_options_for(dir + "/mpi.csv");
  o.contour_out = dir + "/mpi_contour.csv";
  const SweepCommandResult r = run_sweep_command_mpi(o, model, nullptr);
  if (rank == 0) {
    EXPECT_EQ(r.status, SweepStatus::completed);
    EXPECT_EQ(r.cells_computed, r.cells_shard);
    EXPECT_EQ(read_file(o.out), reference);
    EXPECT_EQ(read_file(o.contour_out), read_file(dir + "/one_contour.csv"));
  } else {
    EXPECT_EQ(r.status, SweepStatus::worker);
  }
  MPI_Barrier(MPI_COMM_WORLD);

  // Killed part-way (simulated: the output cut mid-line), then resumed over the ranks.
  SweepCommandOptions cut = mpi_options_for(dir + "/cut.csv");
  if (rank == 0) {
    std::ofstream(cut.out + ".partial", std::ios::binary) << reference.substr(0, reference.size() / 3 + 7);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const SweepCommandResult rc = run_sweep_command_mpi(cut, model, nullptr);
  if (rank == 0) {
    EXPECT_GT(rc.cells_resumed, 0);
    EXPECT_EQ(read_file(cut.out), reference);
  }

  // Stopped by the cancel flag (checked on rank 0 between rounds), then resumed.
  SweepCommandOptions stop = mpi_options_for(dir + "/stop.csv");
  std::atomic<bool> cancel{false};
  std::atomic<int> calls{0};
  sweep::CellModel counting = model;
  counting.evaluate = [&](const sweep::CellInput& in) {
    if (++calls == 100) cancel = true;
    return model.evaluate(in);
  };
  const SweepCommandResult rs = run_sweep_command_mpi(stop, counting, nullptr, &cancel);
  if (rank == 0) {
    EXPECT_EQ(rs.status, SweepStatus::cancelled);
    EXPECT_FALSE(fs::exists(stop.out));
  }
  const SweepCommandResult rs2 = run_sweep_command_mpi(stop, model, nullptr);
  if (rank == 0) {
    EXPECT_EQ(rs2.status, SweepStatus::completed);
    EXPECT_EQ(read_file(stop.out), reference);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

TEST(SweepMpi, AnErrorOnAnyRankReachesEveryRank) {
  if (!launched_by_mpi_launcher()) GTEST_SKIP() << "needs mpirun: ctest -R sweep_mpi_2ranks";
  const std::string dir = shared_dir("error");
  sweep::CellModel model = sweep::synthetic::wave_model();
  const auto base = model.evaluate;
  // The last cell is computed by the last rank.
  const std::int64_t last = mpi_options_for("").grid.cell_count() - 1;
  model.evaluate = [base, last](const sweep::CellInput& in) {
    if (in.index == last) throw InputError("--K", "contact did not separate");
    return base(in);
  };
  try {
    run_sweep_command_mpi(mpi_options_for(dir + "/err.csv"), model, nullptr);
    ADD_FAILURE() << "no error on rank " << session().rank();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--K: contact did not separate");
  }
  // Rank 0's own errors (here: another sweep's file at --out) reach the others too.
  if (session().rank() == 0) std::ofstream(dir + "/other.csv") << "not a sweep\n";
  MPI_Barrier(MPI_COMM_WORLD);
  try {
    run_sweep_command_mpi(mpi_options_for(dir + "/other.csv"), sweep::synthetic::wave_model(), nullptr);
    ADD_FAILURE() << "no error on rank " << session().rank();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a tribolab sweep file"), std::string::npos);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace
}  // namespace tribolab::app
#else  // a build without MPI (the ASan tree of `make test`)

#include "numerics/error.hpp"
#include "sweep/synthetic.hpp"

namespace tribolab::app {
namespace {

TEST(SweepMpi, ABuildWithoutMpiSaysSoInsteadOfRunning) {
  EXPECT_FALSE(built_with_mpi());
  SweepCommandOptions o;
  o.out = "never_written.csv";
  try {
    run_sweep_command_mpi(o, sweep::synthetic::wave_model(), nullptr);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("built without MPI"), std::string::npos) << e.what();
  }
  EXPECT_THROW(MpiSession{}, InputError);
}

}  // namespace
}  // namespace tribolab::app
#endif
