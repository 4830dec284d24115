//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, after the sweeps: the light the dim lights bring, swept on a
// grid twice as coarse as the fine one (DimLightsOf, ScattererTransportLightPasses.h),
// added to the fine grid's arriving light (blending), read trilinearly at each of its
// texels:
//   A(p) += sum_{dim l} E_l a_l(p) T_l(p)
// with the sum as the dim lights' own arriving light holds it (their grid, one texel
// more a side: scatterer_transport_arrive.glsl, scatterer_transport_line_texels.glsl).
// Inside the fine grid the read keeps to the dim grid's texels (its border, where the
// light has crossed no matter, would brighten the fine texels beyond the last coarse
// texel's centre); the fine texture's border reads the dim texture's border.
//============================================================================
in vec2 texCoord;
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform sampler3D st_dimArriving; // the dim lights' arriving light, one texel more a side
uniform vec3 st_gridDims;        // the fine grid
uniform vec3 st_dimDims;         // the dim lights' grid
// Fine grid position -> dim grid position: j * st_gridToDimScale + st_gridToDimOffset.
uniform vec3 st_gridToDimScale;
uniform vec3 st_gridToDimOffset;

void main()
{
  vec3 j = vec3(floor(texCoord * (st_gridDims.xy + 2.0)), st_layer) - vec3(1.0);
  vec3 d = clamp(j * st_gridToDimScale + st_gridToDimOffset, vec3(0.0), st_dimDims - vec3(1.0));
  d = mix(d, vec3(-1.0), lessThan(j, vec3(0.0)));
  d = mix(d, st_dimDims, greaterThanEqual(j, st_gridDims));
  gl_FragData[0] = vec4(texture(st_dimArriving, (d + vec3(1.5)) / (st_dimDims + 2.0)).rgb, 1.0);
}
