// Luminance of a linear colour with Rec. 709 primaries (docs/hdr.md): what the tone mapping, the
// auto exposure's reduction and bloom's HDR bright pass each measure.
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
