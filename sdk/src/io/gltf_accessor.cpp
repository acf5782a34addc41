#include "io/gltf_accessor.h"

#include "io/gltf_precheck.h"

#include <algorithm>
#include <cstring>

namespace prox::io::gltf_detail {
namespace {

struct UseSpec {
  const char* role;
  std::size_t components;
  int type;         // TINYGLTF_TYPE_*
  unsigned floats;  // 1: FLOAT allowed
  unsigned plain;   // bit per integer component type allowed not normalized (see bit_of)
  unsigned normed;  // bit per integer component type allowed normalized
  const char* allowed;

  bool accepts(int accessor_type, int component, bool normalized) const {
    if (accessor_type != type) return false;
    if (component == TINYGLTF_COMPONENT_TYPE_FLOAT) return floats && !normalized;
    return (bit_of(component) & (normalized ? normed : plain)) != 0;
  }
  static unsigned bit_of(int component) {
    switch (component) {
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return 1;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 2;
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return 4;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 8;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return 16;
      default:
        return 0;
    }
  }
};

constexpr unsigned kSmallInts = 1 | 2 | 4 | 8;  // BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT

UseSpec spec_of(AccessorUse use) {
  switch (use) {
    case AccessorUse::Position:
      // Float, or (KHR_mesh_quantization) 8- and 16-bit integers, normalized
      // or not. Accepted whether or not the file declares the extension: the
      // values are unambiguous. The extension does not allow UNSIGNED_INT.
      return {"POSITION",
              3,
              TINYGLTF_TYPE_VEC3,
              1,
              kSmallInts,
              kSmallInts,
              "VEC3 of FLOAT, or of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT with KHR_mesh_quantization"};
    case AccessorUse::Index:
      return {"indices",
              1,
              TINYGLTF_TYPE_SCALAR,
              0,
              2 | 8 | 16,
              0,
              "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"};
    case AccessorUse::MorphPosition:
      return {"a morph target's POSITION",
              3,
              TINYGLTF_TYPE_VEC3,
              1,
              kSmallInts,
              kSmallInts,
              "VEC3 of FLOAT, or of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT with KHR_mesh_quantization"};
    case AccessorUse::Joints:
      return {"JOINTS_n", 4, TINYGLTF_TYPE_VEC4, 0, 2 | 8, 0, "VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT"};
    case AccessorUse::Weights:
      return {"WEIGHTS_n",
              4,
              TINYGLTF_TYPE_VEC4,
              1,
              0,
              2 | 8,
              "VEC4 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT"};
    case AccessorUse::InverseBindMatrix:
      return {"inverseBindMatrices", 16, TINYGLTF_TYPE_MAT4, 1, 0, 0, "MAT4 of FLOAT"};
    case AccessorUse::Time:
      return {"an animation sampler's input", 1, TINYGLTF_TYPE_SCALAR, 1, 0, 0, "SCALAR of FLOAT"};
    case AccessorUse::Vec3Output:
      return {"a translation or scale sampler's output", 3, TINYGLTF_TYPE_VEC3, 1, 0, 0, "VEC3 of FLOAT"};
    case AccessorUse::RotationOutput:
      return {"a rotation sampler's output",
              4,
              TINYGLTF_TYPE_VEC4,
              1,
              0,
              kSmallInts,
              "VEC4 of FLOAT, or of normalized BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT"};
    case AccessorUse::WeightsOutput:
      return {"a weights sampler's output",
              1,
              TINYGLTF_TYPE_SCALAR,
              1,
              0,
              kSmallInts,
              "SCALAR of FLOAT, or of normalized BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT"};
  }
  return {"an accessor", 1, -1, 0, 0, 0, "none"};
}

}  // namespace

std::size_t components_of(AccessorUse use) { return spec_of(use).components; }

const char* component_type_name(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
      return "INT (not a glTF 2.0 type)";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
      return "DOUBLE (not a glTF 2.0 type)";
    default:
      return "an unknown component type";
  }
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "an unknown type";
  }
}

std::size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// One little-endian component; normalized integers map to [-1, 1] or [0, 1]
// by the glTF 2.0 formulas (signed: max(c / (2^(n-1) - 1), -1)).
double read_component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = static_cast<std::int8_t>(p[0]);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = p[0];
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = static_cast<std::int16_t>(static_cast<std::uint16_t>(p[0] | p[1] << 8));
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = static_cast<std::uint16_t>(p[0] | p[1] << 8);
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return read_u32le(p);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      const std::uint32_t bits = read_u32le(p);
      float f;
      std::memcpy(&f, &bits, sizeof f);
      return static_cast<double>(f);
    }
    default:
      return 0.0;
  }
}

// A view's bytes, checked to lie inside its buffer.
Status AccessorReader::buffer_view(int index, const std::string& where, const unsigned char*& data,
                                   std::size_t& length) const {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.bufferViews.size())
    return error(where + ": bufferView " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(model_.bufferViews.size()) + ")");
  const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(index)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
    return error(where + ": bufferView " + std::to_string(index) + " refers to buffer " +
                 std::to_string(view.buffer) + ", which does not exist");
  const std::vector<unsigned char>& buffer = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    return error(where + ": bufferView " + std::to_string(index) + " (byteOffset " +
                 std::to_string(view.byteOffset) + ", byteLength " + std::to_string(view.byteLength) +
                 ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                 std::to_string(buffer.size()) + " bytes)");
  data = buffer.data() + view.byteOffset;
  length = view.byteLength;
  return Status::ok();
}

// `count` elements of `element` bytes, `stride` apart from `offset`, must
// lie within `length` bytes: offset + (count - 1) * stride + element.
Status AccessorReader::check_span(std::uint64_t offset, std::uint64_t count, std::uint64_t stride,
                                  std::uint64_t element, std::uint64_t length,
                                  const std::string& what) const {
  if (count == 0) return Status::ok();
  if (offset > length || element > length - offset || count - 1 > (length - offset - element) / stride)
    return error(what + ": " + std::to_string(count) + " elements of " + std::to_string(element) +
                 " bytes, " + std::to_string(stride) + " apart from byteOffset " + std::to_string(offset) +
                 ", run past the end of the bufferView (" + std::to_string(length) + " bytes)");
  return Status::ok();
}

// Accessor `index` as count * components doubles: the base bufferView (or
// zeros without one), then the sparse substitutions.
Status AccessorReader::read(int index, const std::string& where, AccessorUse use,
                            std::vector<double>& out) const {
  out.clear();
  if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size())
    return error(where + ": accessor " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(model_.accessors.size()) + ")");
  const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
  const std::string what = where + " accessor " + std::to_string(index);
  const int ct = accessor.componentType;

  const UseSpec spec = spec_of(use);
  const std::size_t components = spec.components;
  if (!spec.accepts(accessor.type, ct, accessor.normalized))
    return error(what + ": " + type_name(accessor.type) + " of " +
                 std::string(accessor.normalized ? "normalized " : "") + component_type_name(ct) +
                 " is not a valid type for " + spec.role + " (" + spec.allowed + ")");
  const std::size_t size = component_size(ct);
  const std::size_t element = size * components;
  const std::uint64_t count = accessor.count;
  if (count > kMaxU32)
    return {StatusCode::Unsupported, name_ + ": " + what + ": more than 4294967295 elements"};
  if (accessor.bufferView == -1 && !accessor.sparse.isSparse && count > 0)
    return error(what + ": has neither a bufferView nor sparse values");

  const unsigned char* first = nullptr;
  std::size_t stride = element;
  if (accessor.bufferView != -1) {
    const unsigned char* data = nullptr;
    std::size_t length = 0;
    Status status = buffer_view(accessor.bufferView, what, data, length);
    if (!status) return status;
    const std::size_t view_stride =
        model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)].byteStride;
    if (view_stride != 0 && view_stride < element)
      return error(what + ": bufferView " + std::to_string(accessor.bufferView) + " has byteStride " +
                   std::to_string(view_stride) + ", less than the " + std::to_string(element) +
                   "-byte element");
    if (view_stride != 0) stride = view_stride;
    status = check_span(accessor.byteOffset, count, stride, element, length, what);
    if (!status) return status;
    first = data + accessor.byteOffset;
  }
  out.assign(static_cast<std::size_t>(count) * components, 0.0);  // glTF: no bufferView means zeros
  if (first != nullptr) {
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t c = 0; c < components; ++c)
        out[i * components + c] = read_component(first + i * stride + c * size, ct, accessor.normalized);
  }

  if (accessor.sparse.isSparse) {
    const auto& sparse = accessor.sparse;
    const std::string sparse_what = what + " (sparse)";
    if (sparse.count < 1 || static_cast<std::uint64_t>(sparse.count) > count)
      return error(sparse_what + ": count " + std::to_string(sparse.count) + " is not in [1, " +
                   std::to_string(count) + "]");
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      return error(sparse_what + ": indices of " + component_type_name(index_type) +
                   " (UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT are allowed)");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
      return error(sparse_what + ": negative byteOffset");
    const std::size_t n = static_cast<std::size_t>(sparse.count);
    const std::size_t index_size = component_size(index_type);
    const unsigned char* indices = nullptr;
    const unsigned char* values = nullptr;
    std::size_t length = 0;
    // Both are tightly packed (glTF forbids a byteStride on these views).
    Status status = buffer_view(sparse.indices.bufferView, sparse_what + " indices", indices, length);
    if (status)
      status = check_span(static_cast<std::uint64_t>(sparse.indices.byteOffset), n, index_size, index_size,
                          length, sparse_what + " indices");
    if (status) status = buffer_view(sparse.values.bufferView, sparse_what + " values", values, length);
    if (status)
      status = check_span(static_cast<std::uint64_t>(sparse.values.byteOffset), n, element, element, length,
                          sparse_what + " values");
    if (!status) return status;
    indices += sparse.indices.byteOffset;
    values += sparse.values.byteOffset;
    std::uint64_t previous = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const auto target =
          static_cast<std::uint64_t>(read_component(indices + k * index_size, index_type, false));
      if (target >= count)
        return error(sparse_what + ": index " + std::to_string(target) + " (entry " + std::to_string(k) +
                     ") is past the accessor's " + std::to_string(count) + " elements");
      if (k > 0 && target <= previous)
        return error(sparse_what + ": indices are not strictly increasing (" + std::to_string(previous) +
                     " then " + std::to_string(target) + ")");
      previous = target;
      for (std::size_t c = 0; c < components; ++c)
        out[target * components + c] =
            read_component(values + k * element + c * size, ct, accessor.normalized);
    }
  }
  return Status::ok();
}

}  // namespace prox::io::gltf_detail
