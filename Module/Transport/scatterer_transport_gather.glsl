//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 2b: template in-scattering (layers in one draw, once
// for all lights), with pass 4's multiply scattered and ambient light added
// (scatterer_transport_scattered.glsl): the light each texel receives.
//
// The light a point p of material m receives, scattered once, from the light arriving
// unscattered around it (A = sum_l E_l a_l T_l: scatterer_transport_arriving.glsl):
//   R(p) = sum_j w_j c_j A(p + r_j) / sum_j w_j                     (single scattering)
// - r_j, w_j: the photons of material m's scatterer templates (Lee, Kwon, Shin
//   2016, Eq. 1-5), all templates merged, in mean free paths of m (the paper's
//   lambda) converted to world units (scatterer/Transport.h).
// - c_j: 1 for a photon in m; the colour of material mp for a photon in another
//   material (colour bleeding, section 3.3). Such a photon's offset is rescaled by
//   the speed ratio n_m / n_mp and its weight by the opacity ratio (section 3.4).
// A point outside every material receives A(p) itself.
//
// Which of the three the texel needs comes from the medium pass (st_fineGather, pass
// 0a, scatterer_transport_medium.glsl): the light moves every frame of an orbit, the
// materials do not. The program comes in three variants (ST_GATHER), each layer drawn
// by the cheapest one that serves all its texels (ScattererTransportMediumPasses):
// - ST_GATHER_ARRIVING: no texel of the layer is in a material: R = A;
// - ST_GATHER_TEMPLATES: no photon of the layer lands in another material: the photons
//   need no material look-up (no tint, no rescale);
// - ST_GATHER_ACROSS_MATERIALS: the texels whose photons cross into another material
//   look the material up at each photon.
// A branch does not spare what it skips on every OpenGL: Mesa's llvmpipe runs both
// sides of a branch for a whole SIMD group, so one program with the three cases cost
// 344 ms per light change on the CT head (2 cores), the three variants 52 ms.
//
// A texel whose photons all stay in its material, of a material whose kernel spreads
// at most scatterer::kCentroidReadSpread texels about its centroid c
// (st_atCentroid[m], scatterer::readsAtCentroid), reads A once, at p + c: within
// 3 s G of the photons' mean, G the largest change of A between neighbouring texels
// (the bound is in scatterer/Transport.h). Its loop runs over the centroid alone, the
// kernel's last column; a loop ends for a SIMD group when none of its texels goes on.
//============================================================================
//VTK::Transport::Common
//VTK::Transport::Materials
//VTK::Transport::Arriving
//VTK::Transport::Scattered
//VTK::Transport::StoredGather
in vec2 texCoord;
uniform sampler3D st_fineGather;   // pass 0a: -1 (none), m, or m + ST_MIXED, interior (st_storedGather)
uniform int st_atCentroid[ST_MAX_MATERIALS]; // 1: material m's kernel is read at its centroid
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)

// A dense interior texel's weight in the ray's trilinear read of the light: texels hold
// the light entering them (scatterer_transport_sweep.glsl), a dense interior one hardly
// any (pass 0a, st_isInterior, scatterer_transport_medium.glsl). Each texel stores its
// light times its weight, and its weight in alpha; the read divides the two
// interpolations (st_transportRead), so that a sample between a dense surface's texel
// and the interior behind it reads the surface's light: the interior's share is at
// most 1 / 65 midway (weights 1 and 1/64), where unweighted it was a half, and the
// texel layers showed on dense surfaces as terraces. Among interior texels alone the
// read is their plain trilinear mean.
const float st_interiorWeight = 1.0 / 64.0;

void main()
{
  vec3 j = vec3(floor(texCoord * st_gridDims.xy), st_layer);
  float stored = texelFetch(st_fineGather, ivec3(j), 0).r;
  float gather = st_gatherFrom(stored);
  vec3 single = st_arrivingAt(j);
#if ST_GATHER != ST_GATHER_ARRIVING
  if (gather >= 0.0)
  {
#if ST_GATHER == ST_GATHER_ACROSS_MATERIALS
    bool mixed = gather >= float(ST_MIXED);
#else
    const bool mixed = false;
#endif
    int m = int(gather + 0.5) - (mixed ? ST_MIXED : 0);
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    bool atCentroid = !mixed && st_atCentroid[m] != 0;
    int end = st_kernelCount + (atCentroid ? 1 : 0);
    for (int k = atCentroid ? st_kernelCount : 0; k < end; ++k)
    {
      vec4 photon = st_photon(m, k);
      vec3 offset = photon.xyz;
      float w = photon.w;
      vec3 tint = vec3(1.0);
#if ST_GATHER == ST_GATHER_ACROSS_MATERIALS
      if (mixed)
      {
        int mp = st_materialAt(st_gridToTexture(j + offset));
        if (st_boundary != 0 && mp >= 0 && mp != m)
        {
          offset *= st_speedRatio[m * ST_MAX_MATERIALS + mp];
          w *= st_opacityRatio[m * ST_MAX_MATERIALS + mp];
          mp = st_materialAt(st_gridToTexture(j + offset));
        }
        tint = (st_bleed != 0 && mp >= 0 && mp != m) ? st_matColor[mp] : vec3(1.0);
      }
#endif
      sum += w * tint * st_arrivingAt(j + offset);
      weights += photon.w;
    }
    single = weights > 0.0 ? sum / weights : single;
  }
#endif
  // Premultiplied by the texel's weight in the read (st_transportRead,
  // scatterer_illumination_dec.glsl): 1, or st_interiorWeight for a dense interior texel.
  float weight = st_interiorFrom(stored) ? st_interiorWeight : 1.0;
  gl_FragData[0] = vec4((single + st_scatteredAndAmbient(j)) * weight, weight);
}
