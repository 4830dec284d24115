//VTK::System::Dec
//VTK::Output::Dec
//============================================================================
// Light transport volume, pass 2a: one light's share of the light arriving
// unscattered, E_l a_l T_l (scatterer_transport_arriving.glsl), at each texel of the
// grid and of one texel more on each side (all layers in one draw per light, the lights
// added up by blending). Positional lights pass here, and directional ones swept slice
// by slice in a build of several lights (scatterer_transport_arriving.glsl).
//============================================================================
//VTK::Transport::Common
in vec2 texCoord;
uniform sampler3D st_transmittance;  // T_l, sweep order (st_toSweep); its border reads 1
flat in float st_layer;          // this layer (scatterer_transport_layers_gs.glsl)
uniform vec3 st_lightColor;
uniform vec3 st_lightPosition;
uniform vec3 st_lightFocalDirection; // positional: unit vector from the light to its focal point
uniform int st_lightPositional;
uniform vec3 st_lightAttenuation;
uniform float st_lightConeCos;       // cos(cone angle); <= -1: no cone
uniform float st_lightExponent;

void main()
{
  vec3 j = vec3(floor(texCoord * (st_gridDims.xy + 2.0)), st_layer) - vec3(1.0);
  float a = 1.0;
  if (st_lightPositional != 0)
  {
    vec4 p = st_texToWorld * vec4(st_gridToTexture(j), 1.0);
    vec3 fromLight = p.xyz / p.w - st_lightPosition;
    float d = length(fromLight);
    a = 1.0 / max(dot(st_lightAttenuation, vec3(1.0, d, d * d)), 1.0e-6);
    if (st_lightConeCos > -1.0)
    {
      float c = dot(fromLight / max(d, 1.0e-20), st_lightFocalDirection);
      a *= c < st_lightConeCos ? 0.0 : pow(max(c, 0.0), st_lightExponent);
    }
  }
  gl_FragData[0] = vec4(a * st_lightColor * texture(st_transmittance, st_sweepCoord(j)).r, 1.0);
}
