// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table: the paper's Table 1 for any folder of meshes.
//
//   quality_table MESH_DIR --out OUT_DIR [--segmentations components,voronoi,ours,ours-nosplit,ours-nofallback]
//                 [--methods conformal,lscm,arap] [--time-limit 60] [--jobs 2] [-n 10]
//
// Every mesh x segmentation x method ("case") runs in its own forked child
// process: segmentation, parameterize_patches(), pack_patches(),
// atlas_quality(). The child streams its results to the parent through a
// pipe, one "key<TAB>value" line at a time, so that what it measured before
// a crash or a time-out is kept. The parent runs up to --jobs children at
// once, kills a child that passes --time-limit seconds, and writes
// OUT_DIR/quality_per_mesh.csv (one row per case, in mesh, segmentation,
// method order whatever --jobs is) and OUT_DIR/quality_table.md (the paper's
// layout; see benchmark/Disk_segmentation/README.md and Atlas_quality).
//
// The parent never calls the library (and so never starts TBB threads),
// which keeps fork() safe: each child starts from a single-threaded process.

#include "quality_table_pool.h"
#include "quality_table_support.h"
#include "quality_table_writers.h"

namespace {

bool is_mesh_file(const fs::path& p)
{
  const std::string e = lower(p.extension().string());
  return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl";
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  std::string segmentations = "components,voronoi,ours,ours-nosplit,ours-nofallback";
  std::string methods = "conformal,lscm,arap";
  o.machine_note = "2-core shared VM";

  CLI::App app{ "Atlas quality of several segmentations and parameterization methods on a folder of meshes, "
                "in the layout of Table 1 of the paper (metrics: Atlas_quality in atlas_quality.h)." };
  app.add_option("MESH_DIR", o.mesh_dir, "folder of meshes (.off .obj .ply .stl), read in sorted name order")
    ->required()
    ->check(CLI::ExistingDirectory);
  app.add_option("--out", o.out_dir, "output folder: quality_per_mesh.csv and quality_table.md")->required();
  app.add_option("--segmentations", segmentations, "comma-separated: components, voronoi, ours, ours-nosplit, ours-nofallback")
    ->capture_default_str();
  app.add_option("--methods", methods, "comma-separated: conformal, lscm, arap, mvc, tutte")->capture_default_str();
  app.add_option("--time-limit", o.time_limit, "seconds per case (mesh x segmentation x method)")
    ->capture_default_str()
    ->check(CLI::PositiveNumber);
  app.add_option("--jobs,-j", o.jobs, "cases run at once, each in its own process")
    ->capture_default_str()
    ->check(CLI::Range(1u, 256u));
  app.add_option("-n,--seeds", o.seeds, "number of seeds of voronoi and ours")
    ->capture_default_str()
    ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30));
  app.add_option("--crease-penalty", o.crease_penalty,
                 "crease_penalty of the `ours` segmentations (0: the paper's distance)")
    ->capture_default_str()
    ->check(CLI::Range(0., (std::numeric_limits<double>::max)()));
  app.add_option("--threads", o.threads, "threads per case for parameterize_patches (0: TBB's choice)")
    ->capture_default_str();
  app.add_option("--texture-resolution", o.texture_resolution, "packing and texel-overlap resolution")
    ->capture_default_str()
    ->check(CLI::Range(1u, 16384u));
  app.add_option("--machine-note", o.machine_note, "machine description printed in the table")
    ->capture_default_str();
  app.add_option("--peers", o.peers_file, "CSV of the peers' numbers to print beside ours (see peers.csv)");
  app.add_flag("--quiet,-q", o.quiet, "no progress lines on stderr");
  CLI11_PARSE(app, argc, argv);

  try
  {
    o.segmentations = split_list(segmentations);
    for(const std::string& s : o.segmentations)
      if(std::find(all_segmentations.begin(), all_segmentations.end(), s) == all_segmentations.end())
        throw DS::Input_error("unknown segmentation '" + s + "' (expected components, voronoi, ours, ours-nosplit or ours-nofallback)");
    for(const std::string& m : split_list(methods))
      o.methods.push_back(DS::parameterization_method_from_string(m));
    if(o.segmentations.empty() || o.methods.empty())
      throw DS::Input_error("no segmentation or no method");
  }
  catch(const std::exception& e)
  {
    std::cerr << "quality_table: " << e.what() << std::endl;
    return 2;
  }

  std::vector<fs::path> files;
  for(const fs::directory_entry& entry : fs::directory_iterator(o.mesh_dir))
    if(entry.is_regular_file() && is_mesh_file(entry.path()))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename().string() < b.filename().string(); });
  if(files.empty())
  {
    std::cerr << "quality_table: no .off, .obj, .ply or .stl file in " << o.mesh_dir << std::endl;
    return 2;
  }

  std::vector<Case> cases;
  for(std::size_t m = 0; m < files.size(); ++m)
    for(const std::string& s : o.segmentations)
      for(DS::Parameterization_method method : o.methods)
      {
        Case c;
        c.mesh = m;
        c.segmentation = s;
        c.method = method;
        cases.push_back(c);
      }

  ::signal(SIGPIPE, SIG_IGN);
  std::vector<Result> results;
  const Clock::time_point start = Clock::now();
  try
  {
    fs::create_directories(o.out_dir);
    if(!o.quiet)
      std::cerr << "quality_table: " << files.size() << " meshes, " << cases.size() << " cases, " << o.jobs
                << " at once" << std::endl;
    run_all(o, files, cases, results);
    const double total = seconds_since(start);
    write_csv(fs::path(o.out_dir) / "quality_per_mesh.csv", files, cases, results);
    write_markdown(fs::path(o.out_dir) / "quality_table.md", o, files, cases, results, total);
  }
  catch(const std::exception& e)
  {
    std::cerr << "quality_table: " << e.what() << std::endl;
    return 1;
  }
  std::size_t failed = 0;
  for(const Result& r : results)
    failed += r.failed() ? 1 : 0;
  std::cout << "quality_table: " << cases.size() << " cases on " << files.size() << " meshes, " << failed
            << " failed, in " << fixed(seconds_since(start), 1) << " s; wrote "
            << (fs::path(o.out_dir) / "quality_table.md").string() << " and "
            << (fs::path(o.out_dir) / "quality_per_mesh.csv").string() << std::endl;
  return 0;
}
