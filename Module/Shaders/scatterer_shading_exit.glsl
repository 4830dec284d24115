//ST::IF SURFACE
  // The ray's first dense samples take the light inside their texel (st_surfaceChange).
  for (int st_k = 0; st_k < ST_SURFACE_SAMPLES; ++st_k)
    {
    if (st_k >= st_surfaceCount)
      {
      break;
      }
    g_fragColor.rgb += st_surfaceChange(st_k);
    }
//ST::ENDIF
