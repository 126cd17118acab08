// Loads and kinematic conditions of the explicit cycle, and the order the time loop calls them in
// (docs/architecture.md section 3, docs/theory/elements.md section 0). The objects are built once from the
// Model; they own copies of what they need (functions, node lists) and keep between cycles only what the work
// bookkeeping needs. Times: t = t_n, dt1 = t_n - t_{n-1} (0 at cycle 0), dt2 = t_{n+1} - t_n,
// dt12 = (dt1 + dt2)/2. Every call returning a double returns external work to ADD to W_ext.
//
// SET-UP, once, after the engine has filled NodeState (x = x0 = model coordinates, mass = model node_mass,
// inertia = element inertias, v = w = 0), with the skew frames `skews` (SkewFrames, the axes of t = 0):
//   BoundaryConditions bcs(model, skews);   bcs.set_fixed_bits(s);
//   Sensors            sensors(model);      sensors.update(0.0, 0.0);  // S = sensors.starts()
//   InitialVelocities  inivel(model, skews); inivel.apply(s, 0.0, S);  // returns the initial KE it gave
//                                                                      // (not work)
//   RigidWalls         walls(model);        walls.initialize(s);   // moving walls: + Mass, v = V0
//   TiedInterfaces     ties(model);         ties.initialize(s);    // TYPE2: secondary mass to the segments
//   RigidBodies        bodies(model);       bodies.initialize(s, S);  // ICoG, M, inertia, principal frame
//   ExternalLoads      loads(model, skews, bodies.secondary_flags());
//   ImposedVelocities  impvel(model, skews);
//   bcs.apply(s);                                                  // fixed dofs start at rest
//
// CYCLE n (t, dt1; dt2 once the element step is known), after the engine's skews.update(s) (the moving
// skews of x^n, read by every condition and load below):
//   0. if (inivel.pending()) W += inivel.apply(s, t, S);           // /INIVEL with Tstart > 0 or a sensor
//   1. zero fx_ext.. and mx.. (and fx.. unless the assembly overwrites fx = fx_ext + f_elements);
//      W += loads.apply(s, t, dt1, S);                             // gravity m g, /CLOAD, /PLOAD at t_n
//   2-4. contact, elements, assembly; choose dt2; sensors.update(t, dt2).
//   (S: the sensors' activation times; a load or condition with a sensor reads its function at t - S[k].)
//   4b. ties.transfer_forces(s);                                  // TYPE2: f_s, m_s, K_s to the segments
//   5. a = f/m, aw = m/I (engine), then in this order:
//      walls.apply_wall_node_forces(s);                            // moving walls: previous wall force
//      bodies.gather_and_accelerate(s, t, dt1, S);                 // a_N = F/M, Euler step (dt1: frame)
//      bcs.apply(s);
//      W += impvel.apply(s, t, dt1, dt2, S);                       // a = (v_imp(t + dt2/2) - v)/dt12
//      W += walls.apply(s, dt1, dt2);                              // kinematic contact, slide 0/1/2
//      bcs.apply(s);
//      bodies.secondary_kinematics(s, dt1, dt2);                   // secondaries follow rigidly
//      ties.secondary_kinematics(s, dt1, dt2);                     // TYPE2 nodes onto their segments
//      W += loads.concentrated_load_work(dt2);                     // /CLOAD: 1/2 (F_old+F_new) v dt2
//   6. outputs: KE = sums over all nodes of 1/2 m |v + dt1/2 a|^2 (and rotations) plus
//      bodies.kinetic_correction(s, dt1); wall forces: walls.outputs().
//   7. v += dt12 a, w += dt12 aw, x += dt2 v.
// When an element is deleted: loads.remove_element(type, index) (/PLOAD Idel = 1).
#pragma once

#include "solver/conditions/boundary_conditions.hpp"
#include "solver/conditions/external_loads.hpp"
#include "solver/conditions/functions.hpp"
#include "solver/conditions/rigid_body.hpp"
#include "solver/conditions/rigid_wall_plane.hpp"
#include "solver/conditions/sensors.hpp"
