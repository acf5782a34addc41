// A force preset at another cutoff (proxGetForcePresetAt): the one place a
// preset is scaled, which the CLI's --cutoff and the bindings' worlds call.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"

#include <cmath>

TEST(CApiForcePresetAt, ScalesTheSafetyDistanceAndDecayWithTheCutoff) {
  for (const proxForcePreset preset : {PROX_FORCE_PRESET_HARD, PROX_FORCE_PRESET_SOFT}) {
    SCOPED_TRACE(int(preset));
    proxForceSettings own{}, at{};
    double cutoff = 0.0;
    ASSERT_OK(proxGetForcePreset(preset, &own, &cutoff));
    // At its own cutoff: the preset itself.
    ASSERT_OK(proxGetForcePresetAt(preset, cutoff, &at));
    EXPECT_EQ(at.safetyDistance, own.safetyDistance);
    EXPECT_EQ(at.decayLength, own.decayLength);
    // At three times it: the lengths three times, the maxima and curve kept.
    ASSERT_OK(proxGetForcePresetAt(preset, 3.0 * cutoff, &at));
    EXPECT_DOUBLE_EQ(at.safetyDistance, 3.0 * own.safetyDistance);
    EXPECT_DOUBLE_EQ(at.decayLength, 3.0 * own.decayLength);
    EXPECT_EQ(at.maxForce, own.maxForce);
    EXPECT_EQ(at.maxTorque, own.maxTorque);
    EXPECT_EQ(at.curve, own.curve);
    // A world takes it at that cutoff.
    proxWorldDef def = proxDefaultWorldDef();
    def.force = at;
    def.cutoff = 3.0 * cutoff;
    proxWorldId w{};
    ASSERT_OK(proxCreateWorld(&def, &w));
    ASSERT_OK(proxWorld_Destroy(w));
  }
}

TEST(CApiForcePresetAt, RefusesWhatIsNotACutoffOrAPreset) {
  proxForceSettings f{};
  EXPECT_FAILS(proxGetForcePresetAt(PROX_FORCE_PRESET_HARD, 0.0, &f), PROX_ERROR_INVALID_ARGUMENT, "cutoff");
  EXPECT_FAILS(proxGetForcePresetAt(PROX_FORCE_PRESET_HARD, -0.01, &f), PROX_ERROR_INVALID_ARGUMENT, "cutoff");
  EXPECT_FAILS(proxGetForcePresetAt(PROX_FORCE_PRESET_HARD, NAN, &f), PROX_ERROR_INVALID_ARGUMENT, "cutoff");
  EXPECT_FAILS(proxGetForcePresetAt(static_cast<proxForcePreset>(5), 0.01, &f), PROX_ERROR_INVALID_ARGUMENT,
               "preset");
  EXPECT_FAILS(proxGetForcePresetAt(PROX_FORCE_PRESET_SOFT, 0.01, nullptr), PROX_ERROR_INVALID_ARGUMENT,
               "force is NULL");
}
