  //VTK::Shading::Init
  // Per sample: the illumination varies on the scale of the template radius,
  // so along a ray it is evaluated every st_interval samples and reused in
  // between (and evaluated at once when the material changes).
  // The step counter is the same for all rays at a given loop iteration, so
  // neighbouring rays evaluate together (SIMD-friendly).
  vec3 st_F = vec3(1.0);
  vec3 st_B = vec3(0.0);
//ST::IF PERSAMPLE
  int st_cachedMaterial = -2;
  int st_step = 0;
//ST::ENDIF
