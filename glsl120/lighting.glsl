// Equations 1-5 for one point light, in eye space (Listing 2, corrected; docs/errata.md):
//  * v points from p to the viewer (Eq. 5); Listing 2 uses +normalize(p), which points away.
//  * h is built from the unit l (Eq. 5); Listing 2 adds the unnormalised l, so h ~ l.
// Returns att * (I_diff + I_spec); the ambient term is the fixed-function pass (Eq. 6).
vec3 lighting(vec3 Scolor, vec3 Spos, float Sradius, vec3 p, vec3 n, vec3 Mdiff, vec3 Mspec, float Mshi)
{
    vec3 l = Spos - p;                          // from p towards the light
    float dist = length(l);
    float att = max(0.0, 1.0 - dist / Sradius); // Equation 2
#ifdef LISTING2_LITERAL
    vec3 v = normalize(p);
    vec3 h = normalize(v + l);
    l = l / max(dist, 1e-30);
#else
    l = dist > 0.0 ? l / dist : n;
    vec3 v = -normalize(p);
    vec3 hv = l + v;
    float hl = length(hv);
    vec3 h = hl > 1e-6 ? hv / hl : n;           // l opposite v: no highlight, no NaN
#endif
    vec3 Idiff = max(0.0, dot(l, n)) * Mdiff * Scolor;               // Equation 3
    vec3 Ispec = pow(max(0.0, dot(h, n)), Mshi) * Mspec * Scolor;    // Equation 4
    return att * (Idiff + Ispec);                                    // Equation 1
}

// Shininess in the specular target's 8-bit alpha (Listing 20 reads specular.w): stored as
// log2(M_shi)/11, so the alpha spans M_shi in [1, 2048] with ~3% steps (docs/errata.md).
float decode_shininess(float a)
{
    return exp2(a * 11.0);
}
