// A force preset at another cutoff (proxGetForcePresetAt): the one place a
// preset is scaled, which the CLI's --cutoff and the bindings' worlds call.
#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include "expect.h"

#include <cmath>
#include <string>

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

// proxGetForcePreset(kind, cutoff): the same settings by value under the
// preset's own name, beside the three-argument form of 0.3, which keeps
// working (and is checked in C by the C11 header test).
TEST(CApiForcePresetAt, GetForcePresetTakesAKindAndACutoff) {
  for (const proxForcePreset kind : {PROX_FORCE_PRESET_HARD, PROX_FORCE_PRESET_SOFT}) {
    SCOPED_TRACE(int(kind));
    proxForceSettings at{};
    ASSERT_OK(proxGetForcePresetAt(kind, 0.02, &at));
    const proxForceSettings by_value = proxGetForcePreset(kind, 0.02);
    EXPECT_EQ(by_value.curve, at.curve);
    EXPECT_EQ(by_value.maxForce, at.maxForce);
    EXPECT_EQ(by_value.maxTorque, at.maxTorque);
    EXPECT_EQ(by_value.safetyDistance, at.safetyDistance);
    EXPECT_EQ(by_value.decayLength, at.decayLength);
    proxForceSettings out{};
    ASSERT_OK(proxGetForcePreset(kind, 0.02, &out));
    EXPECT_EQ(out.safetyDistance, at.safetyDistance);
    // The 0.3 form: the preset at its own cutoff.
    double cutoff = 0;
    ASSERT_OK(proxGetForcePreset(kind, &out, &cutoff));
    EXPECT_GT(cutoff, 0.0);
    EXPECT_EQ(proxGetForcePreset(kind, cutoff).safetyDistance, out.safetyDistance);
  }
  // A failure: zeroed settings, which a world refuses, and the reason.
  const proxForceSettings none = proxGetForcePreset(PROX_FORCE_PRESET_HARD, -1.0);
  EXPECT_EQ(none.maxForce, 0.0);
  EXPECT_NE(std::string(proxGetLastError()).find("cutoff"), std::string::npos);
  proxWorldDef def = proxDefaultWorldDef();
  def.force = none;
  proxWorldId w{};
  EXPECT_FAILS(proxCreateWorld(&def, &w), PROX_ERROR_INVALID_ARGUMENT, "maxForce");
}
