// Closed-form two-bone IK for a limb of this skeleton: a ball joint with dofs
// "zxy" (hip, shoulder), a hinge with dof "z" (knee, elbow), and both bones
// hanging along -Y at rest (after ozz IKTwoBoneJob, specialised to Euler dofs
// so that the answer is the joint angles themselves).
//
// Space: everything is in the local space of the start joint's parent (the
// pelvis for a leg), with the origin moved to the start joint. Angles in degrees.
#pragma once

namespace mc::anim {

struct TwoBoneIKJob {
  float upper_length = 0;   // in: start -> hinge (m), > 0
  float lower_length = 0;   // in: hinge -> end (m), > 0
  float target[3] = {0, 0, 0};  // in: end joint target relative to the start joint (m)
  // in: -1 when the hinge bends backwards (knee: negative flexion brings the
  // shin back), +1 when it bends forwards (elbow).
  float hinge_sign = -1;
  float twist_deg = 0;      // in: start joint's Y angle; turns the hinge plane (knee direction)
  // in: fraction of the full reach beyond which targets are pulled in, so the
  // limb never locks straight (1 = no softening).
  float soften = 0.995f;

  // out: start joint "zxy" angles and the hinge "z" angle.
  float* start_zxy = nullptr;  // 3 floats
  float* hinge_z = nullptr;    // 1 float
  // out, optional: true when the end joint lands on `target` exactly (within
  // 1e-4 m); false when the target was out of reach and was clamped.
  bool* reached = nullptr;

  // False when lengths are not positive, outputs are missing, or soften is
  // outside (0, 1].
  bool Validate() const;
  // Never produces NaN: unreachable or degenerate targets are clamped to the
  // nearest reachable point. Returns false only when !Validate().
  bool Run() const;
};

// Runs both jobs, each exactly as its Run() would (the same bits), stage by
// stage in step: a job is a long chain of dependent trigonometry (acos,
// sin and cos, atan2, one after another), and two chains side by side keep
// the processor busy where one leaves it waiting. `ran[i]`: what job i's
// Run() would return. For two limbs solved at once (both legs).
void run_both(const TwoBoneIKJob& first, const TwoBoneIKJob& second, bool ran[2]);

}  // namespace mc::anim
