  //VTK::Shading::Init
  // Per sample: the illumination varies on the scale of the template radius,
  // so along a ray it is evaluated every st_interval samples and reused in
  // between (and evaluated at once when the material changes).
  // The step counter is the same for all rays at a given loop iteration, so
  // neighbouring rays evaluate together (SIMD-friendly).
  vec3 st_F = vec3(1.0);
  vec3 st_B = vec3(0.0);
//ST::IF TRANSPORT
//ST::IF MULTI
  // A vtkMultiVolume: g_dataPos is the texture coordinate of the box around its inputs;
  // VTK's box matrices take it to the world, which st_datasetToTransport takes to the
  // transport texture (its "dataset" is the world here). Once per ray.
  st_toTransport = st_datasetToTransport * in_volumeMatrix[0] * in_textureDatasetMatrix[0];
//ST::ELSE
  // g_dataPos is the current block's texel coordinate (the one block, or one of a
  // partitioned volume's): undoing VTK's per-block cell-to-point offset and applying its
  // per-block texture -> dataset matrix gives the dataset position, which
  // st_datasetToTransport takes to the transport texture. Once per ray.
  st_toTransport =
    st_datasetToTransport * in_textureDatasetMatrix[0] * inverse(in_cellToPoint[0]);
//ST::ENDIF
//ST::IF GROUPED
  st_lightEnd = st_shownLight(st_transportRead(g_dataPos));
//ST::ENDIF
//ST::IF SURFACE
  // The light inside a dense texel (st_surfaceChange): none recorded yet; a sample is
  // dense when its optical depth across a transport texel toward the light, h / d_s times
  // its own, is above 1: alpha > 1 - exp(-d_s / h). Once per ray.
  st_surfaceCount = 0;
  st_surfaceAt = vec4(0.0);
  st_surfaceLeft = vec4(0.0);
  st_surfaceEntry = g_dataPos;
  st_surfaceFirst = 1.0;
  st_rayStart = g_dataPos;
  st_perStep = 1.0 / max(dot(g_dirStep, g_dirStep), 1.0e-30);
  st_rayToWorld = in_volumeMatrix[0] * in_textureDatasetMatrix[0] * inverse(in_cellToPoint[0]);
  st_worldToData = inverse(mat3(st_rayToWorld));
  st_surfaceAlpha = 1.0 - exp(-in_sampleDistance / max(st_surfaceStep(g_dataPos).w, 1.0e-12));
//ST::ENDIF
//ST::ENDIF
//ST::IF PERSAMPLE
  int st_cachedMaterial = -2;
  int st_step = 0;
//ST::ENDIF
