// What the binding needs beside the C API's functions, which are generated
// (Generated/*.g.cs, tools/gen_native.py): the library's name, the callbacks'
// signatures and the helpers that pin, copy and check. Nothing here is
// public: World, Mesh, Body and the devices are the interface.
using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

[assembly: InternalsVisibleTo("Proxima.Tests")]

namespace Proxima
{
    // The callbacks' C signatures; the thunks in Device.cs implement them.
    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    internal delegate int ReadPoseCallback(IntPtr userData, out Pose pose);

    [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
    internal delegate void WriteWrenchCallback(IntPtr userData, ref Wrench wrench);

    internal static partial class Native
    {
#if (UNITY_IOS || UNITY_WEBGL) && !UNITY_EDITOR
        // Statically linked into the player: IL2CPP resolves these at link time.
        internal const string Library = "__Internal";
#else
        internal const string Library = "proxima";
#endif

        /// <summary>A NUL-terminated UTF-8 char array of a C struct, as a string.</summary>
        internal static string CString(byte[] bytes)
        {
            if (bytes == null) return "";
            int length = Array.IndexOf(bytes, (byte)0);
            return System.Text.Encoding.UTF8.GetString(bytes, 0, length < 0 ? bytes.Length : length);
        }

        // Output arrays are passed as pointers the caller pinned: Mono copies a
        // managed array of structs element by element both ways (measured: 20 us
        // for 64 contacts), where pinning costs a GCHandle.

        /// <summary>proxBody_GetContactPatches into managed arrays (either may be null), pinned
        /// for the call; the capacity is the shorter one's length.</summary>
        internal static Result GetContactPatches(BodyId tool, Contact[] contacts, ContactPatch[] patches, out int count)
        {
            int capacity = Math.Min(contacts?.Length ?? int.MaxValue, patches?.Length ?? int.MaxValue);
            if (capacity == int.MaxValue || capacity == 0)
                return proxBody_GetContactPatches(tool, IntPtr.Zero, IntPtr.Zero, 0, out count);
            GCHandle pinContacts = contacts != null ? GCHandle.Alloc(contacts, GCHandleType.Pinned) : default(GCHandle);
            GCHandle pinPatches = patches != null ? GCHandle.Alloc(patches, GCHandleType.Pinned) : default(GCHandle);
            try
            {
                return proxBody_GetContactPatches(tool, contacts != null ? pinContacts.AddrOfPinnedObject() : IntPtr.Zero,
                                                  patches != null ? pinPatches.AddrOfPinnedObject() : IntPtr.Zero,
                                                  capacity, out count);
            }
            finally
            {
                if (contacts != null) pinContacts.Free();
                if (patches != null) pinPatches.Free();
            }
        }

        /// <summary>proxBody_GetContacts into a managed array, pinned for the call.</summary>
        internal static Result GetContacts(BodyId tool, Contact[] contacts, out int count)
        {
            if (contacts == null || contacts.Length == 0) return proxBody_GetContacts(tool, IntPtr.Zero, 0, out count);
            GCHandle pin = GCHandle.Alloc(contacts, GCHandleType.Pinned);
            try
            {
                return proxBody_GetContacts(tool, pin.AddrOfPinnedObject(), contacts.Length, out count);
            }
            finally
            {
                pin.Free();
            }
        }

        /// <summary>proxBody_GetIntersections into managed arrays, pinned for the call.</summary>
        internal static Result GetIntersections(BodyId tool, Vec3[] points, out int pointCount, PolylineInfo[] lines,
                                                out int lineCount)
        {
            GCHandle p = GCHandle.Alloc(points, GCHandleType.Pinned);
            GCHandle l = GCHandle.Alloc(lines, GCHandleType.Pinned);
            try
            {
                return proxBody_GetIntersections(tool, p.AddrOfPinnedObject(), points.Length, out pointCount,
                                                 l.AddrOfPinnedObject(), lines.Length, out lineCount);
            }
            finally
            {
                p.Free();
                l.Free();
            }
        }

        /// <summary>A C string of the library's, copied (UTF-8).</summary>
        internal static string Copy(IntPtr s)
        {
            if (s == IntPtr.Zero) return "";
            int n = 0;
            while (Marshal.ReadByte(s, n) != 0) ++n;
            var bytes = new byte[n];
            Marshal.Copy(s, bytes, 0, n);
            return System.Text.Encoding.UTF8.GetString(bytes);
        }

        internal static byte[] Utf8(string s, string parameter)
        {
            if (s == null) throw new ArgumentNullException(parameter);
            var bytes = new byte[System.Text.Encoding.UTF8.GetByteCount(s) + 1];
            System.Text.Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        /// <summary>Throws the library's error, with its message, unless r is success.
        /// Must run on the thread that made the failing call (the message is per thread).</summary>
        internal static void Check(Result r)
        {
            if (r != Result.Success) throw ProximaException.FromLastError(r);
        }
    }
}
