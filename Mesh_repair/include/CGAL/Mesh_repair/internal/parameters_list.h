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
MESH_REPAIR_PARAMETER(tolerance_edge_length)  // thesis 4.5: sliver edges shorter than this collapse

// hole filling
MESH_REPAIR_PARAMETER(fill_method)               // Fill_method
MESH_REPAIR_PARAMETER(max_hole_edges)            // holes with more border edges are left open
MESH_REPAIR_PARAMETER(sheet_border_ratio)        // outlines of open sheets are left open
MESH_REPAIR_PARAMETER(max_hole_size)             // fraction of the bounding-box diagonal
MESH_REPAIR_PARAMETER(detect_ring_holes)         // bool: bridge islands into their hole
MESH_REPAIR_PARAMETER(hole_filter)               // predicate on a hole description
MESH_REPAIR_PARAMETER(check_self_intersections)  // bool: exact check of every patch
MESH_REPAIR_PARAMETER(fit_quadric)  // bool: advancing front projects new nodes on a fitted quadric
MESH_REPAIR_PARAMETER(curvature_objective)     // Curvature_objective, Pernot eq. 8 or 9
MESH_REPAIR_PARAMETER(objective_nodes)         // Objective_nodes: free, or free and contour
MESH_REPAIR_PARAMETER(topological_grid)        // Topological_grid: disc or refined Liepa
MESH_REPAIR_PARAMETER(force_density)           // Force_density: uniform, inverse length, cotangent
MESH_REPAIR_PARAMETER(area_normalized_forces)  // bool: objective on f_i / A_i
MESH_REPAIR_PARAMETER(fill_constraints)        // Fill_constraints<Point>, Pernot 6.4
MESH_REPAIR_PARAMETER(deformation_report)      // Curvature_deformation_report*, filled on return

// hole-contour cleaning (Pernot 4)
MESH_REPAIR_PARAMETER(remove_badly_oriented_triangles)  // bool, Pernot 4.1
MESH_REPAIR_PARAMETER(preserve_contour_details)         // bool, Pernot Fig. 4b
MESH_REPAIR_PARAMETER(treat_degenerate_triangles)       // bool, Pernot 4.2
MESH_REPAIR_PARAMETER(homogenize_edge_lengths)          // bool, Pernot 4.3
MESH_REPAIR_PARAMETER(split_length_ratio)               // split border edges above ratio x mean
MESH_REPAIR_PARAMETER(collapse_length_ratio)            // collapse border edges below ratio x mean

// genetic algorithms (shape prediction, optimisation, micro-GA)
MESH_REPAIR_PARAMETER(population_size)
MESH_REPAIR_PARAMETER(max_generations)
MESH_REPAIR_PARAMETER(target_fitness)
MESH_REPAIR_PARAMETER(boundary_smoothing_iterations)  // shape prediction: eq. 5.1 passes
MESH_REPAIR_PARAMETER(use_rough_set_simplification)   // bool, shape prediction 5.3.2
MESH_REPAIR_PARAMETER(fitness_weights)            // std::array<double,3>: w_a, w_b, w_c of eq. 5.13
MESH_REPAIR_PARAMETER(curvature_flow_iterations)  // shape prediction: smoothing on the patches
MESH_REPAIR_PARAMETER(surface_tangent_scale)  // micro-GA: 0 input triangles .. 1 full G1 surface
MESH_REPAIR_PARAMETER(cubic_surface_weight)   // deprecated name of surface_tangent_scale
MESH_REPAIR_PARAMETER(slide_feature_nodes)    // micro-GA: nodes inside feature lines slide along
MESH_REPAIR_PARAMETER(convert_to_quads)       // mesh_points: pair triangles into quads

// mesh optimisation (optimize_mesh.h, thesis ch. 7)
MESH_REPAIR_PARAMETER(optimization_mode)          // Optimization_mode: reduction or quality
MESH_REPAIR_PARAMETER(target_face_count)          // reduction stops at this many faces
MESH_REPAIR_PARAMETER(target_face_ratio)          // or at this fraction of the input faces
MESH_REPAIR_PARAMETER(weighing_factor_threshold)  // eq. 7.4: elements with larger d are kept
MESH_REPAIR_PARAMETER(shape_weight)               // w_a of eq. 7.9
MESH_REPAIR_PARAMETER(smoothness_weight)          // w_b of eq. 7.9
MESH_REPAIR_PARAMETER(surrounding_weight)         // w_c of eq. 7.9
MESH_REPAIR_PARAMETER(min_angle_floor_deg)        // reduction: new triangles' smallest angle

// threads
MESH_REPAIR_PARAMETER(number_of_threads)

// automatic repair
MESH_REPAIR_PARAMETER(keep_largest_component)     // bool: drop all but the largest component
MESH_REPAIR_PARAMETER(repair_self_intersections)  // bool: replace self-intersecting faces
MESH_REPAIR_PARAMETER(merge_intersecting_solids)  // bool: union of intersecting closed parts
MESH_REPAIR_PARAMETER(remove_hole_fragments)      // bool: small open pieces in holes removed
MESH_REPAIR_PARAMETER(bridge_through_holes)       // bool: missing walls of through-holes added
MESH_REPAIR_PARAMETER(orient_closed_parts)        // bool: closed parts made to bound a volume

// hole benchmark (hole_benchmark.h)
MESH_REPAIR_PARAMETER(number_of_holes)  // holes punched per mesh
MESH_REPAIR_PARAMETER(hole_radius)      // fraction of the bounding-box diagonal
MESH_REPAIR_PARAMETER(hole_shape)       // Hole_shape
