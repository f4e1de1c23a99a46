// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one list of the package's named parameters. It is included, without
// an include guard, by each place that stamps something out of it: the tags
// and builders (parameters.h), the tags the package reads
// (Parameter_checks.h) and the names the front ends give them
// (IO/Atlas_options.h). Adding a parameter is one line here plus a settings
// reader that reads it; the front ends see it once its option names are set.
//
// CGAL_DISK_SEGMENTATION_PARAMETER(name, disk_uv option, Python keyword):
// a parameter of the interface; the option names are "" where a front end
// does not set it. The front-end ones come first, in the order
// IO::in_user_terms() rewords them.
// CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(name): a parameter of the
// package's tests and benchmarks, in parameters::testing.
//
// What each parameter means is documented on the manual page
// PkgDiskSegmentationNamedParameters and with every function that reads it.

#ifndef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER
#define CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(name) CGAL_DISK_SEGMENTATION_PARAMETER(name, "", "")
#define CGAL_DISK_SEGMENTATION_TESTING_PARAMETER_DEFAULTED
#endif

// The segmentation (segmentation_settings()).
//   number n of farthest-point seeds of the Voronoi segmentation (count)
CGAL_DISK_SEGMENTATION_PARAMETER(number_of_seeds, "-n/--seeds", "n (seeds)")
//   number k of seeds re-sampling a region that is not a disk (count, >= 2)
CGAL_DISK_SEGMENTATION_PARAMETER(number_of_subsamples, "-k/--subsamples", "k (subsamples)")
//   score threshold eps of the greedy merging (double >= 0)
CGAL_DISK_SEGMENTATION_PARAMETER(merge_threshold, "--threshold", "threshold")
//   arcs across bent edges 1 + k (1 - cos theta) times longer (double >= 0; 0: the paper)
CGAL_DISK_SEGMENTATION_PARAMETER(crease_penalty, "--crease-penalty", "crease_penalty")
// The charts (parameterization_settings()).
//   method of every chart (Parameterization_method)
CGAL_DISK_SEGMENTATION_PARAMETER(parameterization_method, "--method", "method")
// The packing (packing_settings()).
//   how charts are placed (Packing_method)
CGAL_DISK_SEGMENTATION_PARAMETER(packing_method, "--packer", "packer")
//   texture width in texels (count)
CGAL_DISK_SEGMENTATION_PARAMETER(texture_resolution, "--resolution", "resolution")
//   texture height in texels, when not square (count)
CGAL_DISK_SEGMENTATION_PARAMETER(texture_height, "--resolution (its height)", "resolution (its height)")
//   gap around every chart in texels (double >= 0)
CGAL_DISK_SEGMENTATION_PARAMETER(padding_in_texels, "--padding", "padding")
//   fixed texel density (double >= 0; 0: fit one page)
CGAL_DISK_SEGMENTATION_PARAMETER(texels_per_unit, "--texels-per-unit", "texels_per_unit")
//   most pages a fixed density may fill (count)
CGAL_DISK_SEGMENTATION_PARAMETER(max_number_of_pages, "--max-pages", "max_pages")
// Every stage.
//   most threads (count; 0: TBB decides)
CGAL_DISK_SEGMENTATION_PARAMETER(number_of_threads, "--threads", "threads")
// The charts and their bound (parameterization_settings(), distortion_bound_parameters()).
//   patches larger than this are split first (count)
CGAL_DISK_SEGMENTATION_PARAMETER(max_chart_faces, "--max-chart-faces", "max_chart_faces")
//   chart budget: merge past the bound down to this (count)
CGAL_DISK_SEGMENTATION_PARAMETER(max_number_of_charts, "--max-charts", "max_charts")
//   largest area-weighted mean |log(s1/s2)| of a chart
CGAL_DISK_SEGMENTATION_PARAMETER(max_angle_distortion, "--max-angle-distortion", "max_angle_distortion")
//   largest area-weighted mean |log(s1 s2)| of a chart
CGAL_DISK_SEGMENTATION_PARAMETER(max_area_distortion, "--max-area-distortion", "max_area_distortion")
//   largest 95th percentile of s1/s2 over a chart
CGAL_DISK_SEGMENTATION_PARAMETER(max_stretch_p95, "--max-stretch-p95", "max_stretch_p95")
//   largest s1/s2 of any triangle
CGAL_DISK_SEGMENTATION_PARAMETER(max_stretch, "--max-stretch", "max_stretch")
//   largest max(s1 s2, 1/(s1 s2)) of any triangle
CGAL_DISK_SEGMENTATION_PARAMETER(max_area_scale, "--max-area-scale", "max_area_scale")
//   smallest UV area / hull area of a large chart, in [0, 1)
CGAL_DISK_SEGMENTATION_PARAMETER(min_convexity, "--min-convexity", "min_convexity")
// Set by the front ends from flags of their own, or not at all.
//   all the bounds at once (Distortion_bound); the six above override it
CGAL_DISK_SEGMENTATION_PARAMETER(distortion_bound, "", "")
//   whether an invalid chart is redone with an injective method (bool)
CGAL_DISK_SEGMENTATION_PARAMETER(use_fallback, "", "")
//   whether region borders lose their saw teeth (bool)
CGAL_DISK_SEGMENTATION_PARAMETER(smooth_borders, "", "")
//   whether adjacent charts meeting the bound together are merged (bool)
CGAL_DISK_SEGMENTATION_PARAMETER(merge_charts, "", "")
//   whether chart borders are rerouted along shorter paths (bool)
CGAL_DISK_SEGMENTATION_PARAMETER(straighten_borders, "", "")
//   the user's parameterizer of every chart (SMP Parameterizer_3 or a factory)
CGAL_DISK_SEGMENTATION_PARAMETER(parameterizer, "", "")
//   receives the seed faces in the order they were chosen
CGAL_DISK_SEGMENTATION_PARAMETER(seeds_output_iterator, "", "")
//   Merge_tree* filled by the segmentation, read by parameterize_patches()
CGAL_DISK_SEGMENTATION_PARAMETER(merge_tree, "", "")
//   callback(stage, done, total); false cancels
CGAL_DISK_SEGMENTATION_PARAMETER(progress_callback, "", "")
//   faces of different values never share a chart (face map)
CGAL_DISK_SEGMENTATION_PARAMETER(face_material_map, "", "")
//   faces of one value are one polygon of the caller's mesh (face map)
CGAL_DISK_SEGMENTATION_PARAMETER(face_polygon_map, "", "")
//   the first farthest-point seed of its component (face)
CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(first_seed)
//   false parameterizes patches that are not disks (a baseline)
CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(require_disk_patches)

#ifdef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER_DEFAULTED
#undef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER
#undef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER_DEFAULTED
#endif
