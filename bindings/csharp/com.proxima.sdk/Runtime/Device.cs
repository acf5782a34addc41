using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using System.Threading;

namespace AOT
{
    /// <summary>Marks the methods native code calls back, so that IL2CPP compiles a
    /// reverse P/Invoke wrapper for each. IL2CPP and Mono's AOT compiler match
    /// it by name, so this assembly, which references no UnityEngine
    /// (noEngineReferences), carries its own, internal so that it never
    /// clashes with UnityEngine's.</summary>
    [AttributeUsage(AttributeTargets.Method)]
    internal sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        public MonoPInvokeCallbackAttribute(Type type) { Type = type; }
        public Type Type { get; }
    }
}

namespace Proxima
{
    /// <summary>A haptic device written in C#: subclass it and attach it with
    /// Body.SetDevice. Both methods are called on Proxima's haptic thread, at
    /// 1 kHz, while the world's threads run: return in microseconds, allocate
    /// nothing, and never call Proxima from them. A garbage collection can stall
    /// them for milliseconds (the safety gate then fades the force); for a tool
    /// driven at frame rate prefer the streamed device.
    ///
    /// An exception thrown by either method is caught (one escaping onto a native
    /// thread would end the process), counted in Exceptions and kept in
    /// LastException; a failed ReadPose counts as "no pose this tick".</summary>
    public abstract class Device
    {
        long exceptions;
        Exception lastException;

        /// <summary>The tool's world pose now, or false when there is none this tick.</summary>
        public abstract bool ReadPose(out Pose pose);

        /// <summary>The force and torque to render: finite, within the world's maxima,
        /// rate-limited.</summary>
        public virtual void WriteWrench(ref Wrench wrench) { }

        /// <summary>How many exceptions the callbacks threw (and Proxima caught).</summary>
        public long Exceptions => Interlocked.Read(ref exceptions);

        /// <summary>The most recent of them, or null.</summary>
        public Exception LastException => Volatile.Read(ref lastException);

        // One static thunk per callback type: IL2CPP can only hand native code
        // static methods, so the device comes back through a GCHandle in userData.
        static readonly ReadPoseCallback readPoseThunk = ReadPoseThunk;
        static readonly WriteWrenchCallback writeWrenchThunk = WriteWrenchThunk;
        static readonly IntPtr readPosePointer = Marshal.GetFunctionPointerForDelegate(readPoseThunk);
        static readonly IntPtr writeWrenchPointer = Marshal.GetFunctionPointerForDelegate(writeWrenchThunk);

        [AOT.MonoPInvokeCallback(typeof(ReadPoseCallback))]
        static int ReadPoseThunk(IntPtr userData, out Pose pose)
        {
            pose = Pose.Identity;
            Device device = null;
            try
            {
                device = (Device)GCHandle.FromIntPtr(userData).Target;
                return device.ReadPose(out pose) ? 1 : 0;
            }
            catch (Exception e)
            {
                device?.Caught(e);
                return 0;
            }
        }

        [AOT.MonoPInvokeCallback(typeof(WriteWrenchCallback))]
        static void WriteWrenchThunk(IntPtr userData, ref Wrench wrench)
        {
            Device device = null;
            try
            {
                device = (Device)GCHandle.FromIntPtr(userData).Target;
                device.WriteWrench(ref wrench);
            }
            catch (Exception e)
            {
                device?.Caught(e);
            }
        }

        void Caught(Exception e)
        {
            try
            {
                Interlocked.Increment(ref exceptions);
                Volatile.Write(ref lastException, e);
            }
            catch
            {
                // Nothing may leave the thunk.
            }
        }

        // The handles that keep attached devices alive, per tool. Freed when the
        // tool gets another device or none, is destroyed, or its world is: then
        // the threads that call the thunks have stopped.
        static readonly object registryLock = new object();
        static readonly Dictionary<BodyKey, GCHandle> attached = new Dictionary<BodyKey, GCHandle>();

        internal static void Attach(BodyId tool, Device device)
        {
            GCHandle handle = GCHandle.Alloc(device);
            DeviceDef def = Native.proxDefaultDeviceDef();
            def.ReadPose = readPosePointer;
            def.WriteWrench = writeWrenchPointer;
            def.UserData = GCHandle.ToIntPtr(handle);
            Result r = Native.proxBody_SetDevice(tool, ref def);
            if (r != Result.Success)
            {
                ProximaException e = ProximaException.FromLastError(r);
                handle.Free();
                throw e;
            }
            lock (registryLock)
            {
                var key = new BodyKey(tool);
                if (attached.TryGetValue(key, out GCHandle old)) old.Free();
                attached[key] = handle;
            }
        }

        internal static void Release(BodyId tool)
        {
            lock (registryLock)
            {
                var key = new BodyKey(tool);
                if (attached.TryGetValue(key, out GCHandle old))
                {
                    old.Free();
                    attached.Remove(key);
                }
            }
        }

        internal static void ReleaseAll(WorldId world)
        {
            lock (registryLock)
            {
                var gone = new List<BodyKey>();
                foreach (var entry in attached)
                    if (entry.Key.WorldIndex1 == world.Index1 && entry.Key.WorldGeneration == world.Generation)
                        gone.Add(entry.Key);
                foreach (BodyKey key in gone)
                {
                    attached[key].Free();
                    attached.Remove(key);
                }
            }
        }

        internal static int AttachedCount
        {
            get { lock (registryLock) return attached.Count; }
        }

        readonly struct BodyKey : IEquatable<BodyKey>
        {
            readonly uint index1, generation;
            public readonly uint WorldIndex1, WorldGeneration;

            public BodyKey(BodyId id)
            {
                index1 = id.Index1;
                generation = id.Generation;
                WorldIndex1 = id.World.Index1;
                WorldGeneration = id.World.Generation;
            }

            public bool Equals(BodyKey o) => index1 == o.index1 && generation == o.generation &&
                                             WorldIndex1 == o.WorldIndex1 && WorldGeneration == o.WorldGeneration;
            public override bool Equals(object obj) => obj is BodyKey k && Equals(k);
            public override int GetHashCode() => (int)(index1 * 31 + generation) ^ (int)(WorldIndex1 << 20);
        }
    }

    /// <summary>The built-in scripted device (proxScriptedDeviceId): a tool moved along a
    /// path of poses, natively, with no managed code on the haptic thread.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct ScriptedDevice
    {
        internal readonly ScriptedDeviceId id;

        internal ScriptedDevice(ScriptedDeviceId id) { this.id = id; }

        /// <summary>What the device has been handed so far.</summary>
        public ScriptedDeviceRecord Record
        {
            get { Native.Check(Native.proxScriptedDevice_GetRecord(id, out ScriptedDeviceRecord r)); return r; }
        }

        /// <summary>Whether the device is alive (not destroyed, nor its world). Any thread.</summary>
        public bool IsValid => Native.proxScriptedDevice_IsValid(id);

        /// <summary>Lets the device go: a tool it holds has no pose from then on (its force
        /// fades out). Game thread.</summary>
        public void Destroy() => Native.Check(Native.proxScriptedDevice_Destroy(id));
    }
}
