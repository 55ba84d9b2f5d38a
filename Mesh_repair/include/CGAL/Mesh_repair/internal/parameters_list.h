// The named parameters that Mesh_repair adds to CGAL's. One line per parameter:
//   MESH_REPAIR_PARAMETER(name)
// generates the tag `CGAL::Mesh_repair::internal_np::name_t`, the chainable member `.name(v)`
// and the free function `CGAL::Mesh_repair::parameters::name(v)`.
// Before adding one, check that CGAL has none of the same meaning (random_seed, geom_traits,
// vertex_point_map, number_of_iterations, fairing_continuity, visitor, ...): reuse those instead.
// No include guard: this file is included several times with different definitions of the macro.

// tolerances and thresholds (detection, stitching)
MESH_REPAIR_PARAMETER(merge_tolerance)            // absolute distance, model units
MESH_REPAIR_PARAMETER(relative_tolerance)         // fraction of the bounding-box diagonal
MESH_REPAIR_PARAMETER(shape_factor_threshold)     // thesis eq. 4.14, normalised to [0,1]
MESH_REPAIR_PARAMETER(aspect_ratio_threshold)     // Pernot eq. 1 (Q)
MESH_REPAIR_PARAMETER(needle_threshold)           // longest / shortest edge ratio
MESH_REPAIR_PARAMETER(cap_threshold_deg)          // largest angle, degrees
MESH_REPAIR_PARAMETER(feature_angle_deg)          // dihedral angle below which an edge is a feature
MESH_REPAIR_PARAMETER(detect_self_intersections)  // bool
MESH_REPAIR_PARAMETER(histogram_bins)             // number of bins of the quality histograms
MESH_REPAIR_PARAMETER(use_cubic_curves)           // bool, thesis 4.3.1

// hole filling
MESH_REPAIR_PARAMETER(fill_method)               // Fill_method
MESH_REPAIR_PARAMETER(max_hole_edges)            // holes with more border edges are left open
MESH_REPAIR_PARAMETER(max_hole_size)             // fraction of the bounding-box diagonal
MESH_REPAIR_PARAMETER(detect_ring_holes)         // bool: bridge islands into their hole
MESH_REPAIR_PARAMETER(hole_filter)               // predicate on a hole description
MESH_REPAIR_PARAMETER(check_self_intersections)  // bool: exact check of every patch

// genetic algorithms (shape prediction, optimisation, micro-GA)
MESH_REPAIR_PARAMETER(population_size)
MESH_REPAIR_PARAMETER(max_generations)
MESH_REPAIR_PARAMETER(target_fitness)

// threads
MESH_REPAIR_PARAMETER(number_of_threads)
