// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// _disk_uv: the Python binding's compiled part. The package disk_uv
// (python/disk_uv/__init__.py) wraps it; keep the checks of user input here,
// in one place, so that every entry point refuses bad arrays the same way.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_GLB.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_OBJ.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Disk_segmentation/IO/Atlas_options.h>
#include <CGAL/Disk_segmentation/IO/atlas_report_JSON.h>
#include <CGAL/Disk_segmentation/IO/packing_warnings.h>
#include <CGAL/Disk_segmentation/IO/internal/Float_texcoords.h>
#include <CGAL/Disk_segmentation/IO/read_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <fstream>
#include <functional>
#include <mutex>
#include <thread>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <sys/resource.h>

namespace py = pybind11;
namespace DS = CGAL::Disk_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, Kernel::Point_2> UV_map;

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Index_array;

// Raised as ValueError by the translator registered below.
struct Bad_argument : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// An argument of the wrong type: raised as disk_uv.ArgumentTypeError, a
// TypeError that is also a ValueError (what earlier versions raised).
struct Bad_type : Bad_argument
{
  using Bad_argument::Bad_argument;
};

// Python needs messages in UTF-8; one naming a file whose name is not
// (bytes from the file system) gets its other bytes as \xNN.
std::string as_utf8(const std::string& text)
{
  std::string out;
  for(std::size_t i = 0; i < text.size();)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    bool valid = length > 0 && i + length <= text.size();
    for(std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if(valid)
    {
      out.append(text, i, length);
      i += length;
      continue;
    }
    static const char hex[] = "0123456789abcdef";
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
    ++i;
  }
  return out;
}

std::string type_name(const py::handle& value) { return py::str(py::type::handle_of(value).attr("__name__")); }

py::array as_numpy_array(const py::handle& object, const char* name)
{
  py::array a = py::array::ensure(object);
  if(!a)
    throw Bad_argument(std::string(name) + " must be a numpy array (or convertible to one)");
  return a;
}

std::string shape_text(const py::array& a)
{
  std::string text = "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d)
    text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

void check_shape(const py::array& a, const char* name, const char* expected)
{
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw Bad_argument(std::string(name) + " must have shape " + expected + ", not " + shape_text(a));
}

// The triangle soup of two arrays, checked as the C++ tool checks a file:
// shapes and dtypes here, then indices, finiteness and manifoldness by
// the tool's own soup check (pinched vertices are kept and counted).
struct Soup
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > faces;
  std::size_t input_vertices = 0;
  std::size_t pinched_vertices_split = 0;
};

Soup soup_from_arrays(const py::handle& vertices_object, const py::handle& faces_object)
{
  const py::array vertices = as_numpy_array(vertices_object, "vertices");
  const py::array faces = as_numpy_array(faces_object, "faces");
  const char vk = vertices.dtype().kind(), fk = faces.dtype().kind();
  if(vk != 'f' && vk != 'i' && vk != 'u')
    throw Bad_argument("vertices must be an array of real numbers, not of dtype " +
                       std::string(py::str(vertices.dtype())));
  if(fk != 'i' && fk != 'u')
    throw Bad_argument("faces must be an array of integers, not of dtype " + std::string(py::str(faces.dtype())));
  check_shape(vertices, "vertices", "(N, 3)");
  check_shape(faces, "faces", "(F, 3)");
  if(fk == 'u' && faces.dtype().itemsize() >= 8)
  {
    // uint64 indices beyond int64 would wrap to negative ones below.
    const auto big = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
    for(py::ssize_t i = 0; i < big.size(); ++i)
      if(big.data()[i] > std::uint64_t(std::numeric_limits<std::int64_t>::max()))
        throw Bad_argument("faces: index " + std::to_string(big.data()[i]) + " is out of range");
  }
  const Double_array v = Double_array::ensure(vertices);
  const Index_array f = Index_array::ensure(faces);
  if(!v || !f)
    throw Bad_argument("vertices and faces could not be read as numbers");

  Soup soup;
  const std::size_t nv = static_cast<std::size_t>(v.shape(0)), nf = static_cast<std::size_t>(f.shape(0));
  soup.input_vertices = nv;
  soup.points.reserve(nv);
  for(std::size_t i = 0; i < nv; ++i)
    soup.points.emplace_back(v.at(i, 0), v.at(i, 1), v.at(i, 2));
  soup.faces.resize(nf);
  for(std::size_t i = 0; i < nf; ++i)
  {
    soup.faces[i].resize(3);
    for(std::size_t j = 0; j < 3; ++j)
    {
      const std::int64_t index = f.at(i, j);
      if(index < 0)
        throw Bad_argument("face #" + std::to_string(i) + " refers to vertex " + std::to_string(index) +
                           "; indices must be non-negative");
      soup.faces[i][j] = static_cast<std::size_t>(index);
    }
  }
  std::string problem = DS::IO::internal::triangle_soup_problem(soup.points, soup.faces, &soup.pinched_vertices_split);
  if(!problem.empty())
  {
    // The check was written for files.
    const std::string file = "the file has only";
    const std::size_t at = problem.find(file);
    if(at != std::string::npos)
      problem.replace(at, file.size(), "vertices has only");
    throw Bad_argument(problem);
  }
  return soup;
}

// The mesh keeps the soup's vertex and face order (vertex i, face i).
void build_mesh(const Soup& soup, Mesh& mesh)
{
  DS::IO::internal::checked_triangle_soup_to_mesh(soup.points, soup.faces, mesh);
}

// Integers: Python's and numpy's (anything with __index__), not bools.
long long integer_option(const py::object& value, const char* name)
{
  if(py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr()))
    throw Bad_type(std::string(name) + " must be an integer, not " + type_name(value));
  const py::int_ integer(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())));
  const long long n = PyLong_AsLongLong(integer.ptr());
  if(n == -1 && PyErr_Occurred())
  {
    PyErr_Clear();
    throw Bad_argument(std::string(name) + " is too large");
  }
  return n;
}

std::size_t count_option(const py::dict& o, const char* name)
{
  const long long n = integer_option(o[name], name);
  if(n < 0)
    throw Bad_argument(std::string(name) + " must be non-negative, not " + std::to_string(n));
  return static_cast<std::size_t>(n);
}

// `resolution`: one integer (a square texture) or a (width, height) pair.
void texture_size_option(const py::dict& o, std::size_t& width, std::size_t& height)
{
  const py::object value = o["resolution"];
  if(py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value))
  {
    const py::sequence pair = value;
    if(pair.size() != 2)
      throw Bad_argument("resolution must be an integer or a (width, height) pair, not a sequence of " +
                         std::to_string(pair.size()));
    py::dict sides;
    sides["resolution (its width)"] = pair[0];
    sides["resolution (its height)"] = pair[1];
    width = count_option(sides, "resolution (its width)");
    height = count_option(sides, "resolution (its height)");
  }
  else
    width = height = count_option(o, "resolution");
  if(width > std::numeric_limits<unsigned int>::max() || height > std::numeric_limits<unsigned int>::max())
    throw Bad_argument("resolution is too large");
}

// Reals: Python's and numpy's numbers, not bools or strings.
double real_option(const py::dict& o, const char* name)
{
  const py::object value = o[name];
  if(py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) || !PyNumber_Check(value.ptr()))
    throw Bad_type(std::string(name) + " must be a number, not " + type_name(value));
  const double x = PyFloat_AsDouble(value.ptr());
  if(x == -1. && PyErr_Occurred())
  {
    PyErr_Clear();
    throw Bad_argument(std::string(name) + " must be a number");
  }
  return x;
}

// One of the names `choices` lists ("a, b or c"), as a string.
std::string choice_option(const py::dict& o, const char* name, const char* choices)
{
  const py::object value = o[name];
  if(!py::isinstance<py::str>(value))
    throw Bad_type(std::string(name) + " must be one of " + choices + " (a string), not " + type_name(value));
  return value.cast<std::string>();
}

DS::Distortion_bound bound_from(const py::dict& o, bool& unbounded)
{
  DS::Distortion_bound bound;
  bound.max_angle_distortion = real_option(o, "max_angle_distortion");
  bound.max_area_distortion = real_option(o, "max_area_distortion");
  bound.max_stretch = real_option(o, "max_stretch");
  bound.max_area_scale = real_option(o, "max_area_scale");
  bound.max_stretch_p95 = real_option(o, "max_stretch_p95");
  bound.min_convexity = real_option(o, "min_convexity");
  unbounded = o["unbounded"].cast<bool>();
  return bound;
}

// Calls visit(h, j) for each halfedge h of face f whose target is corner j
// of the soup's face f: the mesh keeps the soup's vertex and face order.
template <typename Visit>
void for_each_corner(const Mesh& mesh, const Soup& soup, std::size_t f, const Visit& visit)
{
  const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
  for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(face), mesh))
    for(std::size_t j = 0; j < 3; ++j)
      if(std::size_t(mesh.target(h)) == soup.faces[f][j])
        visit(h, j);
}

// The process's peak resident memory so far, in MB, that Atlas.report gives
// as peak_rss_mb: a measure of this process, which the library's report
// leaves to its caller. Linux's VmHWM first (getrusage()'s ru_maxrss may
// hold the peak of a parent's address space from before exec()).
double peak_rss_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, 6, "VmHWM:") == 0)
    {
      std::istringstream kilobytes(line.substr(6));
      double kb = 0;
      if(kilobytes >> kb)
        return kb / 1024.;
    }
  struct rusage usage;
  if(::getrusage(RUSAGE_SELF, &usage) != 0)
    return 0;
  return double(usage.ru_maxrss) / 1024.;  // KB on Linux
}

// Per-corner UVs and chart ids in the soup's face and corner order.
py::dict atlas_result(const Soup& soup, const Mesh& mesh, const Patch_map& patch, const UV_map& uv,
                      const std::string& report)
{
  const std::size_t nf = soup.faces.size();
  py::array_t<double> corner_uvs({ py::ssize_t(nf), py::ssize_t(3), py::ssize_t(2) });
  py::array_t<std::uint32_t> chart_ids = py::array_t<std::uint32_t>(static_cast<py::ssize_t>(nf));
  auto u = corner_uvs.mutable_unchecked<3>();
  auto c = chart_ids.mutable_unchecked<1>();
  for(std::size_t f = 0; f < nf; ++f)
  {
    const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
    c(f) = static_cast<std::uint32_t>(patch[face]);
    for_each_corner(mesh, soup, f, [&](Mesh::Halfedge_index h, std::size_t j) {
      u(f, j, 0) = uv[h].x();
      u(f, j, 1) = uv[h].y();
    });
  }
  py::dict result;
  result["uvs"] = corner_uvs;
  result["chart_ids"] = chart_ids;
  result["report"] = report;
  return result;
}

typedef std::function<bool(const std::string&, std::size_t, std::size_t)> Keep_going;

// Runs `work(keep_going)` (the library's computation, without the GIL) on a
// thread of its own, while the interpreter's thread watches for signals:
// Ctrl-C raises KeyboardInterrupt as soon as the computation's next
// progress report. `progress` (None or a Python callable of (stage, done,
// total)) is called at each report; a return of False cancels
// (DS::Cancelled, raised as disk_uv.Cancelled), and an exception it raises
// cancels and is raised as it is.
void run_interruptible(const py::object& progress, const std::function<void(const Keep_going&)>& work)
{
  std::atomic<bool> stop(false);
  std::exception_ptr python_error, work_error;
  std::mutex python_error_mutex;
  const Keep_going keep_going = [&](const std::string& stage, std::size_t done, std::size_t total) {
    if(stop)
      return false;
    if(progress.is_none())
      return true;
    py::gil_scoped_acquire gil;
    try
    {
      const py::object answer = progress(stage, done, total);
      if(answer.is_none())
        return true;
      // Its __bool__ may raise: that stops the run like any exception of the callback.
      const int truth = PyObject_IsTrue(answer.ptr());
      if(truth < 0)
        throw py::error_already_set();
      return truth != 0;
    }
    catch(py::error_already_set&)
    {
      std::lock_guard<std::mutex> lock(python_error_mutex);
      python_error = std::current_exception();
      stop = true;
      return false;
    }
  };
  {
    py::gil_scoped_release release;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread worker([&] {
      try
      {
        work(keep_going);
      }
      catch(...)
      {
        work_error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while(!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; }))
    {
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        // Runs the Python signal handlers, which only run on this thread.
        if(!stop && PyErr_CheckSignals() != 0)
        {
          std::lock_guard<std::mutex> error_lock(python_error_mutex);
          if(!python_error)
            python_error = std::make_exception_ptr(py::error_already_set());
          stop = true;
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if(python_error)
    std::rethrow_exception(python_error);
  if(work_error)
    std::rethrow_exception(work_error);
}

// An optional (F,) integer array of the options: empty when None.
std::vector<std::int64_t> face_values(const py::dict& o, const char* name, const char* what, const Soup& soup)
{
  std::vector<std::int64_t> values;
  if(o[name].is_none())
    return values;
  const py::array given = as_numpy_array(o[name], name);
  // As for faces: a float array would be truncated (0.1 and 0.9 one id, NaN some id).
  const char kind = given.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw Bad_argument(std::string(name) + " must be an array of integers, not of dtype " +
                       std::string(py::str(given.dtype())));
  const Index_array a = Index_array::ensure(given);
  if(!a || a.ndim() != 1 || std::size_t(a.shape(0)) != soup.faces.size())
    throw Bad_argument(std::string(name) + " must have shape (F,): " + what);
  values.assign(a.data(), a.data() + a.shape(0));
  return values;
}

// The options of atlas() as the library's named parameters, checked (the
// mapping the disk_uv tool uses too: IO/Atlas_options.h).
auto atlas_settings(const py::dict& o, std::string& method_name, std::string& packer_name)
{
  DS::IO::Atlas_options options;
  options.bound = bound_from(o, options.unbounded);
  method_name = options.method = choice_option(o, "method", "arap, conformal, lscm, mvc or tutte");
  packer_name = options.packer = choice_option(o, "packer", "tight or grid");
  std::size_t width = 0, height = 0;
  texture_size_option(o, width, height);
  options.texture_width = static_cast<unsigned int>(width);
  options.texture_height = static_cast<unsigned int>(height);
  const std::size_t threads = count_option(o, "threads");
  if(threads > 4096)
    throw Bad_argument("threads must be at most 4096");
  options.number_of_threads = static_cast<unsigned int>(threads);
  // None: no chart budget.
  if(!o["max_charts"].is_none())
  {
    options.max_number_of_charts = count_option(o, "max_charts");
    if(options.max_number_of_charts == 0)
      throw Bad_argument("max_charts must be None or at least 1");
  }
  options.number_of_seeds = count_option(o, "n");
  options.number_of_subsamples = count_option(o, "k");
  options.merge_threshold = real_option(o, "threshold");
  options.crease_penalty = real_option(o, "crease_penalty");
  options.use_fallback = o["use_fallback"].cast<bool>();
  options.rough_borders = o["rough_borders"].cast<bool>();
  options.max_chart_faces = count_option(o, "max_chart_faces");
  options.padding_in_texels = real_option(o, "padding");
  options.texels_per_unit = real_option(o, "texels_per_unit");
  options.max_number_of_pages = count_option(o, "max_pages");
  return DS::IO::atlas_parameters(options);
}

// The options of atlas() checked without a mesh (the batch checks its
// command line once, before any mesh is read).
void check_atlas_options(const py::dict& o)
{
  std::string method_name, packer_name;
  atlas_settings(o, method_name, packer_name);
}

py::dict run_atlas(const py::handle& vertices, const py::handle& faces, const py::dict& o)
{
  Soup soup = soup_from_arrays(vertices, faces);
  const std::vector<std::int64_t> groups = face_values(o, "face_groups", "one polygon id per face", soup);
  const std::vector<std::int64_t> materials = face_values(o, "materials", "one material id per face", soup);
  std::string method_name, packer_name;
  const auto settings = atlas_settings(o, method_name, packer_name);
  const py::object seed = o["seed"];
  const bool seeded = !seed.is_none();
  unsigned int seed_value = 0;
  if(seeded)
  {
    const long long value = integer_option(seed, "seed");
    if(value < 0 || value > std::numeric_limits<unsigned int>::max())
      throw Bad_argument("seed must be None or an integer between 0 and 4294967295");
    seed_value = static_cast<unsigned int>(value);
  }

  Mesh mesh;
  build_mesh(soup, mesh);
  Patch_map patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  // Both maps are always given (each face its own polygon, one material):
  // one instantiation of uv_atlas() per chain.
  auto polygon = mesh.add_property_map<Mesh::Face_index, std::int64_t>("f:polygon", 0).first;
  auto material = mesh.add_property_map<Mesh::Face_index, std::int64_t>("f:material", 0).first;
  for(Mesh::Face_index f : mesh.faces())
  {
    polygon[f] = groups.empty() ? std::int64_t(f) : groups[std::size_t(f)];
    material[f] = materials.empty() ? 0 : materials[std::size_t(f)];
  }
  const auto with_maps = settings.face_patch_map(patch).face_polygon_map(polygon).face_material_map(material);
  DS::Atlas_report report;
  run_interruptible(o["progress"], [&](const Keep_going& keep_going) {
    if(seeded)
      report = DS::uv_atlas(mesh, uv, with_maps.random_seed(seed_value).progress_callback(keep_going));
    else
      report = DS::uv_atlas(mesh, uv, with_maps.progress_callback(keep_going));
  });
  DS::IO::Read_changes changes;
  changes.pinched_vertices_split = soup.pinched_vertices_split;
  nlohmann::json json =
    DS::IO::atlas_report_json("<arrays>", mesh.number_of_vertices(), report, method_name, packer_name, 0., changes);
  json["peak_rss_mb"] = peak_rss_mb();
  return atlas_result(soup, mesh, patch, uv, json.dump());
}

// atlas([(vertices, faces), ...]): one atlas for several meshes, each
// segmented alone (uv_atlas_of_meshes()); one result per mesh, and the
// common packing's JSON.
py::tuple run_atlas_of_meshes(const py::sequence& parts, const py::dict& o)
{
  for(const char* name : { "face_groups", "materials", "seed" })
    if(!o[name].is_none())
      throw Bad_argument(std::string(name) + " takes one mesh; with several meshes it must be None");
  std::vector<Soup> soups;
  for(std::size_t i = 0; i < parts.size(); ++i)
  {
    const py::object part = parts[i];
    if(!py::isinstance<py::sequence>(part) || py::isinstance<py::str>(part) || py::len(part) != 2)
      throw Bad_type("meshes[" + std::to_string(i) + "] must be a pair (vertices, faces), not " + type_name(part));
    const std::string where = "meshes[" + std::to_string(i) + "]: ";
    try
    {
      soups.push_back(soup_from_arrays(part[py::int_(0)], part[py::int_(1)]));
    }
    catch(const Bad_type& e)
    {
      throw Bad_type(where + e.what());
    }
    catch(const Bad_argument& e)
    {
      throw Bad_argument(where + e.what());
    }
  }
  if(soups.empty())
    throw Bad_argument("meshes is empty: give at least one (vertices, faces) pair");
  std::string method_name, packer_name;
  const auto settings = atlas_settings(o, method_name, packer_name);
  std::vector<Mesh> meshes(soups.size());
  std::vector<const Mesh*> pointers;
  std::vector<Patch_map> patches;
  std::vector<UV_map> uvs;
  for(std::size_t i = 0; i < soups.size(); ++i)
  {
    build_mesh(soups[i], meshes[i]);
    pointers.push_back(&meshes[i]);
    patches.push_back(meshes[i].add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first);
    uvs.push_back(meshes[i].add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first);
  }
  DS::Multi_mesh_atlas_report report;
  run_interruptible(o["progress"], [&](const Keep_going& keep_going) {
    try
    {
      report = DS::uv_atlas_of_meshes(pointers, uvs, patches, settings.progress_callback(keep_going));
    }
    catch(const DS::Input_error& e)
    {
      std::string message = e.what();
      if(message.compare(0, 6, "mesh #") == 0)
        message = "meshes[" + message.substr(6, message.find(':') - 6) + "]" + message.substr(message.find(':'));
      throw DS::Input_error(message);
    }
  });
  py::list results;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    DS::IO::Read_changes changes;
    changes.pinched_vertices_split = soups[i].pinched_vertices_split;
    // The pages of this mesh's charts only: the common packing is returned once.
    nlohmann::json json = DS::IO::mesh_in_atlas_report_json("<arrays>", meshes[i].number_of_vertices(), report, i,
                                                             method_name, packer_name, changes);
    json["total_charts"] = report.first_chart.back();
    json["peak_rss_mb"] = peak_rss_mb();
    results.append(atlas_result(soups[i], meshes[i], patches[i], uvs[i], json.dump()));
  }
  return py::make_tuple(results, DS::IO::packing_report_json(report.packing).dump());
}

py::array_t<std::uint32_t> run_segment(const py::handle& vertices, const py::handle& faces, const py::dict& o)
{
  Soup soup = soup_from_arrays(vertices, faces);
  Mesh mesh;
  build_mesh(soup, mesh);
  Patch_map patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  const auto settings = DS::parameters::number_of_seeds(count_option(o, "n"))
                          .number_of_subsamples(count_option(o, "k"))
                          .merge_threshold(real_option(o, "threshold"))
                          .crease_penalty(real_option(o, "crease_penalty"));
  run_interruptible(o["progress"], [&](const Keep_going& keep_going) {
    DS::segment_into_disks(mesh, patch, settings.progress_callback(keep_going));
  });
  py::array_t<std::uint32_t> ids(py::ssize_t(mesh.number_of_faces()));
  auto out = ids.mutable_unchecked<1>();
  for(Mesh::Face_index f : mesh.faces())
    out(py::ssize_t(std::size_t(f))) = static_cast<std::uint32_t>(patch[f]);
  return ids;
}

// xatlas's output from per-corner UVs: one output vertex per input vertex
// and chart (and UV, should a chart hold a vertex twice), in the order the
// faces first use them.
py::tuple xatlas_arrays(const py::handle& faces_object, const py::handle& uvs_object, const py::handle& charts_object)
{
  const Index_array faces = Index_array::ensure(as_numpy_array(faces_object, "faces"));
  const Double_array uvs = Double_array::ensure(as_numpy_array(uvs_object, "uvs"));
  const Index_array charts = Index_array::ensure(as_numpy_array(charts_object, "chart_ids"));
  if(!faces || !uvs || !charts || faces.ndim() != 2 || faces.shape(1) != 3 || uvs.ndim() != 3 ||
     uvs.shape(0) != faces.shape(0) || uvs.shape(1) != 3 || uvs.shape(2) != 2 || charts.ndim() != 1 ||
     charts.shape(0) != faces.shape(0))
    throw Bad_argument("faces (F, 3), uvs (F, 3, 2) and chart_ids (F,) do not match");
  const py::ssize_t nf = faces.shape(0);
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t> > outputs;  // (vertex, chart) -> output vertices
  std::vector<std::uint32_t> vmapping;
  std::vector<std::array<float, 2> > out_uvs;
  std::size_t collapsed = 0;
  for(py::ssize_t f = 0; f < nf; ++f)
    if(DS::IO::internal::collapses_in_float({ { uvs.at(f, 0, 0), uvs.at(f, 1, 0), uvs.at(f, 2, 0) } },
                                            { { uvs.at(f, 0, 1), uvs.at(f, 1, 1), uvs.at(f, 2, 1) } }))
      ++collapsed;
  if(collapsed > 0)
    throw Bad_argument("xatlas's float32 UVs cannot hold this atlas: " +
                       DS::IO::internal::collapsed_in_float_message(collapsed));
  py::array_t<std::uint32_t> indices({ nf, py::ssize_t(3) });
  auto ix = indices.mutable_unchecked<2>();
  for(py::ssize_t f = 0; f < nf; ++f)
    for(py::ssize_t j = 0; j < 3; ++j)
    {
      const std::uint64_t vertex = std::uint64_t(faces.at(f, j)), chart = std::uint64_t(charts.at(f));
      const std::array<float, 2> uv{ { float(uvs.at(f, j, 0)), float(uvs.at(f, j, 1)) } };
      std::vector<std::uint32_t>& candidates = outputs[(vertex << 32) ^ chart];
      std::uint32_t found = std::numeric_limits<std::uint32_t>::max();
      for(std::uint32_t k : candidates)
        if(out_uvs[k] == uv)
          found = k;
      if(found == std::numeric_limits<std::uint32_t>::max())
      {
        found = static_cast<std::uint32_t>(vmapping.size());
        candidates.push_back(found);
        vmapping.push_back(static_cast<std::uint32_t>(vertex));
        out_uvs.push_back(uv);
      }
      ix(f, j) = found;
    }
  py::array_t<std::uint32_t> vm(py::ssize_t(vmapping.size()));
  std::copy(vmapping.begin(), vmapping.end(), vm.mutable_data());
  py::array_t<float> uv_array({ py::ssize_t(out_uvs.size()), py::ssize_t(2) });
  auto ua = uv_array.mutable_unchecked<2>();
  for(std::size_t k = 0; k < out_uvs.size(); ++k)
  {
    ua(py::ssize_t(k), 0) = out_uvs[k][0];
    ua(py::ssize_t(k), 1) = out_uvs[k][1];
  }
  return py::make_tuple(vm, indices, uv_array);
}

// A mesh read by the C++ tool's readers, as (vertices, faces) arrays.
py::tuple load_mesh(const std::string& path, bool repair, bool triangulate)
{
  DS::IO::Read_options options;
  options.repair = repair;
  options.triangulate = triangulate;
  Mesh mesh;
  {
    py::gil_scoped_release release;
    DS::IO::read_triangle_mesh(path, mesh, options);
  }
  py::array_t<double> vertices({ py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3) });
  py::array_t<std::int64_t> faces({ py::ssize_t(mesh.number_of_faces()), py::ssize_t(3) });
  auto v = vertices.mutable_unchecked<2>();
  auto f = faces.mutable_unchecked<2>();
  for(Mesh::Vertex_index i : mesh.vertices())
    for(int d = 0; d < 3; ++d)
      v(py::ssize_t(std::size_t(i)), d) = mesh.point(i)[d];
  for(Mesh::Face_index i : mesh.faces())
  {
    py::ssize_t j = 0;
    for(Mesh::Vertex_index w : CGAL::vertices_around_face(mesh.halfedge(i), mesh))
      f(py::ssize_t(std::size_t(i)), j++) = std::int64_t(std::size_t(w));
  }
  return py::make_tuple(vertices, faces);
}

// The atlas of arrays as the bytes of an OBJ or GLB file (the package
// writes them atomically).
py::bytes atlas_file(const std::string& format, const py::handle& vertices, const py::handle& faces,
                     const py::handle& uvs_object, const py::handle& charts_object)
{
  Soup soup = soup_from_arrays(vertices, faces);
  const Double_array uvs = Double_array::ensure(as_numpy_array(uvs_object, "uvs"));
  const Index_array charts = Index_array::ensure(as_numpy_array(charts_object, "chart_ids"));
  const py::ssize_t nf = py::ssize_t(soup.faces.size());
  if(!uvs || !charts || uvs.ndim() != 3 || uvs.shape(0) != nf || uvs.shape(1) != 3 || uvs.shape(2) != 2 ||
     charts.ndim() != 1 || charts.shape(0) != nf)
    throw Bad_argument("the atlas does not match the mesh: uvs must have shape (F, 3, 2) and chart_ids (F,)");
  Mesh mesh;
  build_mesh(soup, mesh);
  Patch_map patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  for(py::ssize_t f = 0; f < nf; ++f)
  {
    const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
    if(charts.at(f) < 0)
      throw Bad_argument("chart_ids must be non-negative");
    patch[face] = std::size_t(charts.at(f));
    for_each_corner(mesh, soup, std::size_t(f), [&](Mesh::Halfedge_index h, std::size_t j) {
      uv[h] = Kernel::Point_2(uvs.at(f, py::ssize_t(j), 0), uvs.at(f, py::ssize_t(j), 1));
    });
  }
  std::ostringstream out;
  if(format == "obj")
    DS::IO::write_atlas_OBJ(out, mesh, patch, uv);
  else if(format == "glb")
    DS::IO::write_atlas_GLB(out, mesh, patch, uv);
  else
    throw Bad_argument("unknown format '" + format + "'");
  return py::bytes(out.str());
}

} // namespace

PYBIND11_MODULE(_disk_uv, m)
{
  m.doc() = "Compiled part of disk_uv (use the disk_uv package)";
  static py::exception<Bad_type> argument_type_error(m, "ArgumentTypeError",
                                                      py::make_tuple(py::handle(PyExc_TypeError), py::handle(PyExc_ValueError)));
  static py::exception<DS::Cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const DS::Cancelled& e)
    {
      cancelled(as_utf8(e.what()).c_str());
    }
    catch(const Bad_type& e)
    {
      argument_type_error(as_utf8(e.what()).c_str());
    }
    catch(const Bad_argument& e)
    {
      PyErr_SetString(PyExc_ValueError, as_utf8(e.what()).c_str());
    }
    catch(const DS::Input_error& e)
    {
      PyErr_SetString(PyExc_ValueError,
                      as_utf8(DS::IO::in_user_terms(e.what(), DS::IO::Front_end::python)).c_str());
    }
    catch(const DS::IO::File_error& e)
    {
      PyErr_SetString(PyExc_ValueError, as_utf8(e.what()).c_str());
    }
  });
  m.def("atlas", &run_atlas, py::arg("vertices"), py::arg("faces"), py::arg("options"));
  m.def("atlas_of_meshes", &run_atlas_of_meshes, py::arg("meshes"), py::arg("options"));
  m.def("check_atlas_options", &check_atlas_options, py::arg("options"));
  // The packing warnings in the tool's wording, with Python's names; "" when there is none.
  m.def("sparse_packing_warning",
        [](double efficiency, std::size_t pages, std::size_t charts, const std::string& resolution, double padding,
           double texels_per_unit) {
          return DS::IO::sparse_packing_warning(efficiency, pages, charts, resolution, padding, texels_per_unit,
                                                DS::IO::Front_end::python);
        },
        py::arg("efficiency"), py::arg("pages"), py::arg("charts"), py::arg("resolution"), py::arg("padding"),
        py::arg("texels_per_unit"));
  m.def("charts_below_a_texel_warning",
        [](std::size_t tiny, std::size_t charts, const std::string& resolution, double texels_per_unit) {
          return DS::IO::charts_below_a_texel_warning(tiny, charts, resolution, texels_per_unit,
                                                      DS::IO::Front_end::python);
        },
        py::arg("tiny"), py::arg("charts"), py::arg("resolution"), py::arg("texels_per_unit"));
  m.def("segment", &run_segment, py::arg("vertices"), py::arg("faces"), py::arg("options"));
  m.def("xatlas_arrays", &xatlas_arrays, py::arg("faces"), py::arg("uvs"), py::arg("chart_ids"));
  // "N" -> N, "WxH" -> (W, H), anything else -> None: the tool's --resolution.
  m.def("parse_texture_size", [](const std::string& text) -> py::object {
    unsigned int width = 0, height = 0;
    if(!DS::IO::parse_texture_size(text, width, height))
      return py::none();
    if(text.find('x') == std::string::npos)
      return py::int_(width);
    return py::make_tuple(width, height);
  }, py::arg("text"));
  m.def("load", &load_mesh, py::arg("path"), py::arg("repair"), py::arg("triangulate"));
  m.def("atlas_file", &atlas_file, py::arg("format"), py::arg("vertices"), py::arg("faces"), py::arg("uvs"),
        py::arg("chart_ids"));
  m.attr("default_parameterization_method") = DS::to_string(DS::default_parameterization_method);
  m.attr("default_merge_threshold") = DS::regular_polygon_threshold(DS::default_merge_threshold_sides);
  m.attr("default_number_of_seeds") = DS::default_number_of_seeds;
  m.attr("default_crease_penalty") = DS::default_crease_penalty;
  m.attr("default_number_of_subsamples") = DS::default_number_of_subsamples;
  m.attr("default_texture_resolution") = DS::default_texture_resolution;
  m.attr("default_padding") = DS::default_padding_in_texels;
  m.attr("default_max_pages") = DS::default_max_number_of_pages;
  m.attr("default_max_chart_faces") = DS::default_max_chart_faces;
  const DS::Distortion_bound bound;
  m.attr("default_max_angle_distortion") = bound.max_angle_distortion;
  m.attr("default_max_area_distortion") = bound.max_area_distortion;
  m.attr("default_max_stretch") = bound.max_stretch;
  m.attr("default_max_area_scale") = bound.max_area_scale;
  m.attr("default_max_stretch_p95") = bound.max_stretch_p95;
  m.attr("default_min_convexity") = bound.min_convexity;
}
