using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxXrDeviceDef: the app's OpenXR objects and the device's settings. Start
    /// from XrDeviceSettings.Default and set GetInstanceProcAddr, Instance, Session,
    /// BaseSpace, PoseAction (and HapticAction, SubactionPath): handles and paths are
    /// ulong, xrGetInstanceProcAddr an IntPtr, as Unity's OpenXR plugin has them
    /// (OpenXRFeature.xrGetInstanceProcAddr, xrInstance, xrSession). SessionState is an
    /// XrSessionState value (5: FOCUSED, the default).</summary>
    public partial struct XrDeviceSettings
    {
        /// <summary>Every field at its default (proxDefaultXrDeviceDef). Any thread.</summary>
        public static XrDeviceSettings Default => XrDevice.Call(() => Native.proxDefaultXrDeviceDef());
    }

    /// <summary>One of the bindings XrDevice.GetSuggestedBindings fills: OpenXR's
    /// XrActionSuggestedBinding, for the app's xrSuggestInteractionProfileBindings.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct XrActionSuggestedBinding
    {
        public ulong Action;
        /// <summary>An XrPath ("/user/hand/right/input/grip/pose").</summary>
        public ulong Binding;
    }

    /// <summary>An XR controller holding a tool (proxXrDeviceId, docs/openxr.md): its grip
    /// pose moves the tool and the rendered force comes back as its vibration, from the
    /// device's own native thread through the app's xrGetInstanceProcAddr, with no managed
    /// code on the way. The app owns OpenXR: create the device with World.CreateXrDevice
    /// after it attached its action sets, attach it with Body.SetDevice; the app keeps
    /// polling events (forward each session state to OnSessionState), syncing actions
    /// and running frames (OnFrame). It lives until Destroy or its world's end: destroy
    /// it before the app destroys its session, spaces or actions. Present when the
    /// native library was built with PROX_WITH_OPENXR (else Unsupported).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct XrDevice
    {
        internal readonly XrDeviceId id;

        internal XrDevice(XrDeviceId id) { this.id = id; }

        /// <summary>Forward every session state change the app polls (an XrSessionState
        /// value, as Unity's OpenXRFeature.OnSessionStateChange gives it). Game thread.</summary>
        public void OnSessionState(int state)
        {
            XrDeviceId device = id;
            Native.Check(Call(() => Native.proxXrDevice_OnSessionState(device, state)));
        }

        /// <summary>Once a frame, after xrWaitFrame and xrSyncActions: the frame state's
        /// predicted display time and period (XrTime, XrDuration: ns). A headless runtime
        /// that predicts 0 has no frame to report: skip the call. Game thread.</summary>
        public void OnFrame(long predictedDisplayTime, long predictedDisplayPeriod)
        {
            XrDeviceId device = id;
            Native.Check(Call(() => Native.proxXrDevice_OnFrame(device, predictedDisplayTime, predictedDisplayPeriod)));
        }

        /// <summary>Optional: an XrTime the runtime gave the app, about now (an event's time
        /// > 0): the device's clock when the runtime offers no other. Game thread.</summary>
        public void OnRuntimeTime(long time)
        {
            XrDeviceId device = id;
            Native.Check(Call(() => Native.proxXrDevice_OnRuntimeTime(device, time)));
        }

        /// <summary>What the device did since it was created. Any thread.</summary>
        public XrDeviceStats Stats
        {
            get
            {
                XrDeviceId device = id;
                XrDeviceStats s = default(XrDeviceStats);
                Native.Check(Call(() => Native.proxXrDevice_GetStats(device, out s)));
                return s;
            }
        }

        /// <summary>Whether the device is alive (not destroyed, nor its world). Any thread.</summary>
        public bool IsValid
        {
            get
            {
                XrDeviceId device = id;
                return Call(() => (bool)Native.proxXrDevice_IsValid(device));
            }
        }

        /// <summary>Stops its thread (a vibration playing is stopped) and destroys its
        /// action space: a tool it holds has no pose from then on (its force fades out).
        /// Game thread.</summary>
        public void Destroy()
        {
            XrDeviceId device = id;
            Native.Check(Call(() => Native.proxXrDevice_Destroy(device)));
        }

        internal DeviceDef GetDeviceDef()
        {
            XrDeviceId device = id;
            DeviceDef def = default(DeviceDef);
            Native.Check(Call(() => Native.proxXrDevice_GetDeviceDef(device, out def)));
            return def;
        }

        internal static XrDevice Create(WorldId world, XrDeviceSettings settings)
        {
            XrDeviceId device = default(XrDeviceId);
            Native.Check(Call(() => Native.proxWorld_CreateXrDevice(world, ref settings, out device)));
            return new XrDevice(device);
        }

        /// <summary>Creates Proxima's pose and vibration actions, "namePrefix_grip" and
        /// "namePrefix_haptic", in the app's action set for /user/hand/left and
        /// /user/hand/right (proxXrCreateActions), before the app attaches the set. Any
        /// thread.</summary>
        public static void CreateActions(IntPtr getInstanceProcAddr, ulong instance, ulong actionSet, string namePrefix,
                                         out ulong poseAction, out ulong hapticAction)
        {
            byte[] prefix = Native.Utf8(namePrefix, nameof(namePrefix));
            ulong pose = 0, haptic = 0;
            Native.Check(Call(() => Native.proxXrCreateActions(getInstanceProcAddr, instance, actionSet, prefix,
                                                               out pose, out haptic)));
            poseAction = pose;
            hapticAction = haptic;
        }

        /// <summary>The bindings Proxima's actions need in an interaction profile
        /// ("/interaction_profiles/khr/simple_controller", ...) for a hand ("left", "right"
        /// or "/user/hand/right"), for the app to merge into its one
        /// xrSuggestInteractionProfileBindings call for that profile
        /// (proxXrGetSuggestedBindings). hapticAction may be 0. ProximaException
        /// (Unsupported) for a profile Proxima does not know. Any thread.</summary>
        public static XrActionSuggestedBinding[] GetSuggestedBindings(IntPtr getInstanceProcAddr, ulong instance,
                                                                      string interactionProfile, string hand,
                                                                      ulong poseAction, ulong hapticAction)
        {
            byte[] profile = Native.Utf8(interactionProfile, nameof(interactionProfile));
            byte[] handUtf8 = Native.Utf8(hand, nameof(hand));
            var bindings = new XrActionSuggestedBinding[4];
            for (;;)
            {
                int count = 0;
                GCHandle pin = GCHandle.Alloc(bindings, GCHandleType.Pinned);
                Result r;
                try
                {
                    IntPtr at = pin.AddrOfPinnedObject();
                    int capacity = bindings.Length;
                    r = Call(() => Native.proxXrGetSuggestedBindings(getInstanceProcAddr, instance, profile, handUtf8,
                                                                     poseAction, hapticAction, at, capacity,
                                                                     out count));
                }
                finally
                {
                    pin.Free();
                }
                if (r == Result.Capacity && count > bindings.Length)
                {
                    bindings = new XrActionSuggestedBinding[count];
                    continue;
                }
                Native.Check(r);
                var filled = new XrActionSuggestedBinding[count];
                Array.Copy(bindings, filled, count);
                return filled;
            }
        }

        // The OpenXR functions are missing from a library built without them: the
        // first call of one says so, instead of an EntryPointNotFoundException.
        internal static T Call<T>(Func<T> call)
        {
            try
            {
                return call();
            }
            catch (EntryPointNotFoundException e)
            {
                throw new ProximaException(Result.Unsupported,
                    "this native library has no OpenXR device: it was built without PROX_WITH_OPENXR (" + e.Message + ")");
            }
        }

        public override string ToString() => "XrDevice(" + id.Index1 + "/" + id.Generation + ")";
    }
}
