#include "Element.h"

namespace rs::ladder {

bool isEdge(ContactKind kind) {
    return kind != ContactKind::NormallyOpen && kind != ContactKind::NormallyClosed;
}

} // namespace rs::ladder
