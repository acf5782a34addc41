#include "geometry/types.h"

namespace prox {

const char* feature_kind_name(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::Vertex:
      return "vertex";
    case FeatureKind::Edge:
      return "edge";
    case FeatureKind::Face:
      return "face";
  }
  return "unknown";  // not a valid FeatureKind value
}

}  // namespace prox
