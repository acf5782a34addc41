// Generated from sdk/include/proxima/base.h by bindings/csharp/tools/gen_native.py:
// do not edit. Regenerate with `python3 bindings/csharp/tools/gen_native.py`
// (docs/csharp.md); ctest csharp.generated fails while this file is stale.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxResult</summary>
    public enum Result
    {
        Success = 0,
        /// <summary>NULL, NaN, out of range, malformed def</summary>
        InvalidArgument = -1,
        /// <summary>null, destroyed or foreign id</summary>
        InvalidHandle = -2,
        /// <summary>empty, non-finite or degenerate mesh data</summary>
        InvalidMesh = -3,
        /// <summary>a file cannot be read</summary>
        File = -4,
        /// <summary>a file's content is malformed</summary>
        Parse = -5,
        /// <summary>valid input using an unsupported feature</summary>
        Unsupported = -6,
        /// <summary>header and library disagree</summary>
        VersionMismatch = -7,
        /// <summary>called from a thread the function does not allow</summary>
        WrongThread = -8,
        /// <summary>an output buffer is too small (the count says how big)</summary>
        Capacity = -9,
        /// <summary>a bug in Proxima: please report it with the message</summary>
        Internal = -10,
        /// <summary>the world's threads are running: stop them first</summary>
        Busy = -11,
    }

    /// <summary>proxVersion: The library's version (compare with PROX_VERSION_* of this header). Any thread.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public partial struct Version
    {
        public int Major;
        public int Minor;
        public int Patch;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr proxResultString(Result result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern IntPtr proxGetLastError();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        internal static extern Version proxGetVersion();
    }
}
