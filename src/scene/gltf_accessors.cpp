// Reading glTF accessors (gltf_internal.h): every index and byte range checked in 64 bits before a
// byte is read, sparse accessors applied, normalized integers mapped as glTF 2.0 says.
#include <cmath>
#include <cstring>
#include <string>

#include "scene/gltf_internal.h"

namespace dsr::gltf {

using std::string;

namespace {

const char* type_word(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    }
    return "an unknown type";
}

const char* component_word(int ct) {
    switch (ct) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE (5120)";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE (5121)";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT (5122)";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT (5123)";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT (5124)";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT (5125)";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT (5126)";
    }
    return "an unknown component type";
}

// One component at p as a double, normalized as glTF 2.0 (section 3.11) maps it.
double component(const unsigned char* p, int ct, bool normalized) {
    switch (ct) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
        int32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? std::max(v / 2147483647.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? v / 4294967295.0 : v;
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

// a + b and a * b, or false on overflow of 64 bits.
bool add(uint64_t a, uint64_t b, uint64_t& r) { return !__builtin_add_overflow(a, b, &r); }
bool mul(uint64_t a, uint64_t b, uint64_t& r) { return !__builtin_mul_overflow(a, b, &r); }

// The bytes of buffer view `view` (checked against its buffer's data), for use at `user`.
struct ViewBytes {
    const unsigned char* data = nullptr;
    uint64_t size = 0;
    uint64_t stride = 0;  // 0: tightly packed
};
ViewBytes view_bytes(const Context& ctx, int view, const string& user) {
    const auto& views = ctx.tm.bufferViews;
    if (view < 0 || size_t(view) >= views.size())
        ctx.fail(user, "expected a buffer view index below " + std::to_string(views.size()) + ", got " + std::to_string(view));
    const tinygltf::BufferView& bv = views[size_t(view)];
    const string vp = "/bufferViews/" + std::to_string(view);
    if (bv.buffer < 0 || size_t(bv.buffer) >= ctx.tm.buffers.size())
        ctx.fail(vp + "/buffer", "expected a buffer index below " + std::to_string(ctx.tm.buffers.size()) + ", got " +
                                     std::to_string(bv.buffer));
    const auto& data = ctx.tm.buffers[size_t(bv.buffer)].data;
    uint64_t end = 0;
    if (!add(bv.byteOffset, bv.byteLength, end) || end > data.size())
        ctx.fail(vp, "expected bytes within buffer " + std::to_string(bv.buffer) + "'s " + std::to_string(data.size()) +
                         ", got byteLength " + std::to_string(bv.byteLength) + " at byteOffset " + std::to_string(bv.byteOffset));
    if (bv.byteStride != 0 && (bv.byteStride < 4 || bv.byteStride > 252 || bv.byteStride % 4 != 0))
        ctx.fail(vp + "/byteStride", "expected a multiple of 4 in [4, 252], got " + std::to_string(bv.byteStride));
    ViewBytes v;
    v.data = data.data() + bv.byteOffset;
    v.size = bv.byteLength;
    v.stride = bv.byteStride;
    return v;
}

// Checks that `count` elements of `elem` bytes, `stride` apart from `offset`, lie within `size`.
void check_range(const Context& ctx, const string& ptr, uint64_t offset, uint64_t stride, uint64_t count, uint64_t elem,
                 uint64_t size, const string& view_name) {
    uint64_t span = 0, end = 0;
    if (count == 0) return;
    if (!mul(stride, count - 1, span) || !add(offset, span, end) || !add(end, elem, end) || end > size)
        ctx.fail(ptr, "expected " + std::to_string(count) + " elements of " + std::to_string(elem) + " bytes, " +
                          std::to_string(stride) + " apart from byte " + std::to_string(offset) + ", within " + view_name +
                          "'s " + std::to_string(size) + " bytes");
}

}  // namespace

int type_components(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    }
    return 0;
}

int component_bytes(int ct) {
    switch (ct) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    }
    return 0;
}

size_t accessor_count(const Context& ctx, int index, const string& user) {
    if (index < 0 || size_t(index) >= ctx.tm.accessors.size())
        ctx.fail(user, "expected an accessor index below " + std::to_string(ctx.tm.accessors.size()) + ", got " +
                           std::to_string(index));
    const tinygltf::Accessor& a = ctx.tm.accessors[size_t(index)];
    const string ap = "/accessors/" + std::to_string(index);
    if (a.count < 1 || a.count > kMaxElements)
        ctx.fail(ap + "/count", "expected a count in [1, " + std::to_string(kMaxElements) + "], got " + std::to_string(a.count) +
                                    (a.count > kMaxElements ? " (an absurd size)" : ""));
    return a.count;
}

Values read_accessor(Context& ctx, int index, const string& user, const AccessorRule& rule) {
    const size_t count = accessor_count(ctx, index, user);
    const tinygltf::Accessor& a = ctx.tm.accessors[size_t(index)];
    const string ap = "/accessors/" + std::to_string(index);
    const string used = " (for " + user + ")";
    bool type_ok = false;
    string types;
    for (int t : rule.types) {
        type_ok |= t == a.type;
        types += string(types.empty() ? "" : " or ") + type_word(t);
    }
    if (!type_ok) ctx.fail(ap + "/type", "expected " + types + used + ", got " + type_word(a.type));
    bool ct_ok = false;
    string cts;
    for (int c : rule.component_types) {
        ct_ok |= c == a.componentType;
        cts += string(cts.empty() ? "" : ", ") + component_word(c);
    }
    if (!ct_ok) ctx.fail(ap + "/componentType", "expected one of " + cts + used + ", got " + std::to_string(a.componentType));
    if (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                         a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        ctx.fail(ap + "/normalized", string("expected false for ") + component_word(a.componentType) + ", got true");

    Values out;
    out.count = count;
    out.comps = type_components(a.type);
    out.component_type = a.componentType;
    out.normalized = a.normalized;
    const uint64_t csize = uint64_t(component_bytes(a.componentType));
    const uint64_t elem = csize * uint64_t(out.comps);
    out.v.assign(count * size_t(out.comps), 0.0);

    if (a.bufferView >= 0) {
        const ViewBytes vb = view_bytes(ctx, a.bufferView, ap + "/bufferView");
        const uint64_t stride = vb.stride ? vb.stride : elem;
        if (stride < elem)
            ctx.fail("/bufferViews/" + std::to_string(a.bufferView) + "/byteStride",
                     "expected at least the element size " + std::to_string(elem) + " of accessor " + std::to_string(index) +
                         ", got " + std::to_string(stride));
        check_range(ctx, ap, a.byteOffset, stride, count, elem, vb.size, "buffer view " + std::to_string(a.bufferView));
        for (size_t i = 0; i < count; ++i) {
            const unsigned char* p = vb.data + a.byteOffset + stride * i;
            for (int c = 0; c < out.comps; ++c) out.v[i * size_t(out.comps) + size_t(c)] = component(p + csize * uint64_t(c), a.componentType, a.normalized);
        }
    } else if (!a.sparse.isSparse) {
        ctx.fail(ap, "expected a bufferView or sparse values, got neither");
    }

    if (a.sparse.isSparse) {
        const string sp = ap + "/sparse";
        const auto& s = a.sparse;
        if (s.count < 1 || size_t(s.count) > count)
            ctx.fail(sp + "/count", "expected a count in [1, " + std::to_string(count) + "], got " + std::to_string(s.count));
        const int ict = s.indices.componentType;
        if (ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            ict != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            ctx.fail(sp + "/indices/componentType",
                     "expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " + std::to_string(ict));
        if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
            ctx.fail(sp, "expected byte offsets >= 0");
        const ViewBytes ib = view_bytes(ctx, s.indices.bufferView, sp + "/indices/bufferView");
        const ViewBytes vb = view_bytes(ctx, s.values.bufferView, sp + "/values/bufferView");
        const uint64_t isize = uint64_t(component_bytes(ict));
        check_range(ctx, sp + "/indices", uint64_t(s.indices.byteOffset), isize, uint64_t(s.count), isize, ib.size,
                    "buffer view " + std::to_string(s.indices.bufferView));
        check_range(ctx, sp + "/values", uint64_t(s.values.byteOffset), elem, uint64_t(s.count), elem, vb.size,
                    "buffer view " + std::to_string(s.values.bufferView));
        for (size_t k = 0; k < size_t(s.count); ++k) {
            const double target = component(ib.data + uint64_t(s.indices.byteOffset) + isize * k, ict, false);
            if (!(target < double(count)))
                ctx.fail(sp + "/indices", "expected indices below the accessor's count " + std::to_string(count) +
                                              ", got " + num(target) + " at " + std::to_string(k));
            const unsigned char* p = vb.data + uint64_t(s.values.byteOffset) + elem * k;
            for (int c = 0; c < out.comps; ++c)
                out.v[size_t(target) * size_t(out.comps) + size_t(c)] = component(p + csize * uint64_t(c), a.componentType, a.normalized);
        }
    }

    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
        for (size_t i = 0; i < out.v.size(); ++i)
            if (!std::isfinite(out.v[i]))
                ctx.fail(ap, "expected finite numbers" + used + ", got " + num(out.v[i]) + " in element " +
                                 std::to_string(i / size_t(out.comps)));
    return out;
}

}  // namespace dsr::gltf
