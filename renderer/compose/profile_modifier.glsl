// The profile modifiers of Carnecky et al. Eqs. 10-11, applied to β and γ before compositing
// (compose/smart_compose.comp, and compose/modify_profile.comp for the host's blend).
// TLAB_MODIFIER: 0 none, 1 exp (Eq. 10), 2 pow (Eq. 11), a define rather than a uniform: llvmpipe
// evaluates both sides of an `if` under a mask, so with a uniform every fragment also computed
// the modifier it did not use.
uniform float uP;

float modifyProfile(float u) {
  u = clamp(u, 0.0, 1.0);
#if TLAB_MODIFIER == 1
  return (exp(-uP * (1.0 - u)) - exp(-uP)) / (1.0 - exp(-uP));  // Eq. 10
#elif TLAB_MODIFIER == 2
  return pow(u, uP);  // Eq. 11
#else
  return u;
#endif
}
