/* Proxima: real HID devices through hidapi (docs/devices.md#hid-devices).
 *
 * The 3Dconnexion SpaceMouse family (6-DOF pucks), the Sony DualShock 4 and
 * the DualSense drive a tool: each axis, past a dead zone and through a
 * response curve, is a velocity that the device's own thread integrates into
 * the tool's pose; the haptic loop reads that pose through a lock-free
 * handoff and hands back the rendered wrench, which the same device thread
 * turns into rumble, the DualSense's trigger resistance and the light bar,
 * rate-limited. Force-feedback joysticks and wheel bases (USB HID PID, as
 * OpenFFBoard and the Arduino Joystick-with-FFB library speak it) push back:
 * their position is the tool's, inside a workspace, and the wrench becomes
 * a constant-force effect. Present when the library was built with
 * PROX_WITH_HIDAPI. */
#ifndef PROXIMA_HID_H
#define PROXIMA_HID_H

#include <proxima/proxima.h>

#ifdef __cplusplus
extern "C" {
#endif

/* How a device's reports are read (the table of known ids: docs/devices.md). */
typedef enum proxHidProfile {
  PROX_HID_PROFILE_NONE = 0,
  PROX_HID_SPACEMOUSE_SPLIT =
      1, /* SpaceNavigator and siblings: report 1 translation, 2 rotation, 3 buttons */
  PROX_HID_SPACEMOUSE_COMBINED = 2, /* SpaceMouse Wireless and newer: report 1 with all six axes */
  PROX_HID_DUALSHOCK4 = 3,          /* Sony DualShock 4 (USB) */
  PROX_HID_DUALSENSE = 4,           /* Sony DualSense (USB) */
  /* HID PID force feedback, recognised from the report descriptor: */
  PROX_HID_PID_JOYSTICK = 5, /* two force axes (a stick) */
  PROX_HID_PID_WHEEL = 6,    /* one force axis (a wheel base) */
  PROX_HID_PROFILE_FORCE32 = 0x7FFFFFFF
} proxHidProfile;

/* A supported device present now. Strings are UTF-8 and NUL-terminated
 * (cut to fit). */
typedef struct proxHidDeviceInfo {
  uint16_t vendorId, productId;
  proxHidProfile profile;
  int32_t interfaceNumber;
  uint16_t usagePage, usage;
  char name[128];  /* manufacturer and product */
  char serial[64]; /* may be empty */
  char path[256];  /* for proxHidDeviceDef.path */
} proxHidDeviceInfo;

/* Lists the supported devices present now into infos[0 .. capacity) and
 * their number in *count; PROX_ERROR_CAPACITY when they did not all fit
 * (infos may be NULL with capacity 0 to ask). Any thread. */
PROX_API proxResult proxEnumerateHidDevices(proxHidDeviceInfo* infos, int32_t capacity, int32_t* count);

typedef struct proxHidDeviceId {
  uint32_t index1;   /* index + 1; 0 is null */
  uint32_t reserved; /* the slot's generation */
  proxWorldId world;
} proxHidDeviceId;

typedef struct proxHidDeviceDef {
  int32_t apiVersion; /* PROX_API_VERSION, set by proxDefaultHidDeviceDef() */
  const char* path; /* a proxHidDeviceInfo.path, or NULL: the first supported device matching ... */
  uint16_t vendorId, productId; /* ... these ids (0: any) */
  proxPose initialPose;         /* the tool's pose at open, and where the re-centre button puts it */
  proxVec3 referencePoint;      /* in the tool's frame: the point rotations turn about */
  double linearSpeed;           /* m/s at full deflection, >= 0 (default 0.1) */
  double angularSpeed;          /* rad/s at full deflection, >= 0 (default 1.0) */
  double deadZone;         /* [0, 0.9]: the fraction of each axis's travel ignored about rest (default 0.1) */
  double responseExponent; /* [1, 5]: past the dead zone, the rescaled deflection to this power (default 2) */
  proxQuat
      deviceToWorld;   /* rotates the device's frame (x right, y up, z towards the user) into the world's */
  double rumbleForce;  /* N, > 0: the force at which rumble is full (default 3) */
  double triggerForce; /* N, > 0: the force at which the DualSense trigger's resistance is full (default 3) */
  double outputRate;   /* Hz, (0, 250]: the most output reports a second (default 250; a PID device
                          sends at most one report a millisecond, whatever this says) */
  /* Force-feedback (PID) devices. Position control: the tool's travel at
   * full deflection about initialPose along the device frame's x (the stick's
   * X, right) and z (its Y, towards the user), in m; for a wheel, its turn
   * about the device frame's z, in rad. 0 (default): 0.1 m, or 1 rad. */
  double workspace;
  /* N (N m for a wheel) at full magnitude, > 0 (default 5): the magnitude a
   * PID device takes is a fraction of what the device is set to. */
  double maxForce;
  /* The sign of the force on each device axis, the stick's X and Y: 1 as
   * DirectInput pushes, -1 the other way, 0 (default) the firmware's known
   * convention (the Arduino library's is -1, every other +1). */
  int32_t forceSignX, forceSignY;
  /* What the device renders stably, as proxDeviceDef.maxStiffness and
   * damping say (N/m and N s/m; 0, the default: no limit, no damping). A
   * force-feedback stick's firmware and motor decide it: measure it. */
  double maxStiffness;
  double damping;
  int32_t internalValue;
  int32_t reserved;
} proxHidDeviceDef;

PROX_API proxHidDeviceDef proxDefaultHidDeviceDef(void);

/* Where a PID device's constant-force effect is. */
typedef enum proxHidForceEffect {
  PROX_HID_EFFECT_NONE = 0,      /* not a PID device, or not created yet */
  PROX_HID_EFFECT_PLAYING = 1,   /* created, started and renewed */
  PROX_HID_EFFECT_FULL = 2,      /* the device had no free effect block: input only */
  PROX_HID_EFFECT_ERROR = 3,     /* the device could not create it: input only */
  PROX_HID_EFFECT_NO_ANSWER = 4, /* Block Load never answered: input only */
  PROX_HID_EFFECT_STOPPED = 5,   /* stopped and freed (closed, or unplugged) */
  PROX_HID_EFFECT_FORCE32 = 0x7FFFFFFF
} proxHidForceEffect;

/* What a HID device did. Counts since it was opened. */
typedef struct proxHidDeviceStats {
  proxHidProfile profile;
  proxBool connected;      /* open and answering now */
  uint64_t reportsRead;    /* input reports decoded */
  uint64_t malformed;      /* input reports ignored: unknown id, too short or too long */
  uint64_t outputsWritten; /* output reports written */
  uint64_t failedWrites;   /* output reports the device refused */
  uint64_t disconnects;    /* times it stopped answering (unplugged) */
  uint64_t reconnects;     /* times it was found again and reopened */
  uint64_t poseReads;      /* haptic ticks that asked for the pose */
  uint64_t noPoseTicks;    /* ... and got none (disconnected or closed) */
  double lastReportAge;    /* s since the last input report (-1 before the first) */
  /* PID devices: */
  uint64_t forceUpdates;     /* Set Constant Force reports written */
  uint64_t effectsCreated;   /* constant-force effects created (one more at each reconnection) */
  double lastForceMagnitude; /* the last magnitude sent, a fraction of maxForce in [-1, 1] */
  double maxForceMagnitude;  /* the largest |magnitude| sent, in [0, 1] */
  proxHidForceEffect forceEffect;
  int32_t reserved;
} proxHidDeviceStats;

/* Opens a device and starts its thread (reads, integrates, writes outputs).
 * PROX_ERROR_FILE when no supported device matches or it cannot be opened.
 * The device lives until proxHidDevice_Destroy or its world's destruction
 * (devices.h says how every device is let go of). Game thread. */
PROX_API proxResult proxWorld_CreateHidDevice(proxWorldId world, const proxHidDeviceDef* def,
                                              proxHidDeviceId* device);
/* Deprecated: proxWorld_CreateHidDevice under its old name (kept until at least 0.5). */
PROX_API proxResult proxWorld_OpenHidDevice(proxWorldId world, const proxHidDeviceDef* def,
                                            proxHidDeviceId* device);
/* The def that attaches it with proxBody_SetDevice. Game thread. */
PROX_API proxResult proxHidDevice_GetDeviceDef(proxHidDeviceId device, proxDeviceDef* def);
/* Game thread. */
PROX_API proxResult proxHidDevice_GetStats(proxHidDeviceId device, proxHidDeviceStats* stats);
/* The tool's pose as the device last integrated it. Game thread. */
PROX_API proxResult proxHidDevice_GetPose(proxHidDeviceId device, proxPose* pose);
/* Stops its thread and closes it; a tool still holding it has no pose from
 * then on (the force fades). Safe while the world's threads run. Game thread. */
PROX_API proxResult proxHidDevice_Destroy(proxHidDeviceId device);
/* Deprecated: proxHidDevice_Destroy under its old name (kept until at least 0.5). */
PROX_API proxResult proxHidDevice_Close(proxHidDeviceId device);
/* Whether the id names a live (open) HID device. Any thread. */
PROX_API proxBool proxHidDevice_IsValid(proxHidDeviceId device);

#ifdef __cplusplus
}
#endif

#endif /* PROXIMA_HID_H */
