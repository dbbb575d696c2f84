// The shadow stage: each visible shadowed light's map, drawn before the light passes.
#pragma once

namespace dsr {

class ShadowStage {
public:
    ShadowStage() = default;
};

}  // namespace dsr
