/* Prints the size of every public struct of proxima.h, and the offsets of the
 * fields that follow padding, as a C compiler lays them out: what the C#
 * binding's StructLayoutTests compare Marshal.SizeOf and OffsetOf against.
 * One "name value" per line. */
#include <proxima/proxima.h>

#include <stddef.h>
#include <stdio.h>

#define SIZE(T) printf(#T " %zu\n", sizeof(T))
#define OFFSET(T, f) printf(#T "." #f " %zu\n", offsetof(T, f))

int main(void) {
  SIZE(proxBool);
  SIZE(proxResult);
  SIZE(proxVersion);
  SIZE(proxWorldId);
  SIZE(proxMeshId);
  SIZE(proxBodyId);
  SIZE(proxVec3);
  SIZE(proxQuat);
  SIZE(proxPose);
  SIZE(proxForceSettings);
  SIZE(proxWorldDef);
  SIZE(proxMeshDef);
  SIZE(proxMeshInfo);
  SIZE(proxRigInfo);
  SIZE(proxSkinInfo);
  SIZE(proxAnimationInfo);
  SIZE(proxBodyDef);
  SIZE(proxContact);
  SIZE(proxContactPatch);
  SIZE(proxWrench);
  SIZE(proxPolylineInfo);
  SIZE(proxWorldStats);
  SIZE(proxDeviceDef);
  SIZE(proxScriptedDeviceId);
  SIZE(proxScriptedDeviceDef);
  SIZE(proxScriptedDeviceRecord);
  SIZE(proxStreamMode);
  SIZE(proxStreamDeviceId);
  SIZE(proxStreamDeviceDef);
  SIZE(proxStreamDeviceStats);
  SIZE(proxHapticTiming);
  SIZE(proxThreadsDef);
  SIZE(proxThreadStats);
  SIZE(proxSafetyStats);
  SIZE(proxHapticSample);
  SIZE(proxMeshStats);
  SIZE(proxSearchStats);
  SIZE(proxTrackStats);
  SIZE(proxIntersectionStats);
  SIZE(proxPatchSettings);
  SIZE(proxPatchStats);
  OFFSET(proxForceSettings, maxForce);
  OFFSET(proxSkinInfo, jointCount);
  OFFSET(proxAnimationInfo, duration);
  OFFSET(proxAnimationInfo, channelCount);
  OFFSET(proxThreadsDef, traceCapacity);
  OFFSET(proxHapticSample, force);
  OFFSET(proxHapticSample, flags);
  OFFSET(proxHapticSample, closestDistance);
  OFFSET(proxHapticSample, tick);
  OFFSET(proxWorldDef, cutoff);
  OFFSET(proxWorldDef, internalValue);
  OFFSET(proxMeshDef, indices);
  OFFSET(proxMeshDef, triangleCount);
  OFFSET(proxMeshInfo, boundsMin);
  OFFSET(proxBodyDef, pose);
  OFFSET(proxBodyDef, referencePoint);
  OFFSET(proxBodyDef, toolMode);
  OFFSET(proxBodyDef, couplingAngularDamping);
  OFFSET(proxBodyDef, internalValue);
  OFFSET(proxContact, pointTool);
  OFFSET(proxContact, distance);
  OFFSET(proxContact, featureOther);
  OFFSET(proxContactPatch, extent);
  OFFSET(proxWrench, clipped);
  OFFSET(proxPolylineInfo, closed);
  OFFSET(proxDeviceDef, userData);
  OFFSET(proxScriptedDeviceDef, secondsPerPose);
  OFFSET(proxScriptedDeviceRecord, allFinite);
  OFFSET(proxStreamDeviceDef, delay);
  OFFSET(proxStreamDeviceDef, internalValue);
  OFFSET(proxStreamDeviceStats, meanSampleInterval);
  OFFSET(proxThreadsDef, staleAfter);
  OFFSET(proxThreadsDef, hapticTiming);
  OFFSET(proxThreadsDef, spinMargin);
  OFFSET(proxThreadsDef, lockMemory);
  OFFSET(proxThreadsDef, internalValue);
  OFFSET(proxThreadStats, targetRate);
  OFFSET(proxThreadStats, periodP999);
  OFFSET(proxThreadStats, timing);
  OFFSET(proxThreadStats, sleepTimer);
  OFFSET(proxMeshStats, hierarchyBytes);
  OFFSET(proxSearchStats, nodePairs);
  OFFSET(proxTrackStats, distanceEvaluations);
  OFFSET(proxPatchStats, intersectingPairs);
  OFFSET(proxPatchStats, cutNodePairs);
  return 0;
}
