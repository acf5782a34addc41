// The value types of the C API beyond their fields. Their fields, field for
// field with the headers (blittable and sequential, so arrays of them cross
// P/Invoke without copying or conversion), and the enums are generated into
// Generated/*.g.cs by tools/gen_native.py; a partial declaration here must
// add no instance field (C# leaves the order of fields across partial
// declarations undefined). Every size is checked against C's in the tests.
using System;
using System.Runtime.InteropServices;

namespace Proxima
{
    /// <summary>proxBool: a 32-bit boolean (0 false, anything else true).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Bool32 : IEquatable<Bool32>
    {
        readonly int value;
        public Bool32(bool b) { value = b ? 1 : 0; }
        public static implicit operator bool(Bool32 b) => b.value != 0;
        public static implicit operator Bool32(bool b) => new Bool32(b);
        public bool Equals(Bool32 other) => (value != 0) == (other.value != 0);
        public override bool Equals(object obj) => obj is Bool32 b && Equals(b);
        public override int GetHashCode() => value != 0 ? 1 : 0;
        public override string ToString() => value != 0 ? "true" : "false";
    }

    // The structs' fields are generated (Generated/*.g.cs); what they have
    // beyond fields is written here.

    /// <summary>The library's version (proxVersion).</summary>
    public partial struct Version
    {
        public Version(int major, int minor, int patch) { Major = major; Minor = minor; Patch = patch; }

        /// <summary>The C API version this binding was written against.</summary>
        public static Version Binding => new Version(0, 4, 0);

        /// <summary>The version of the native library actually loaded.</summary>
        public static Version Library
        {
            get
            {
                try
                {
                    return Native.proxGetVersion();
                }
                catch (DllNotFoundException e)
                {
                    throw new DllNotFoundException(
                        "Proxima's native library (libproxima) could not be loaded. In Unity it belongs in the " +
                        "package's Runtime/Plugins/<platform>/ (bindings/csharp/fill_plugins.sh copies it from a " +
                        "build); elsewhere put it beside Proxima.dll or on the library path. (" + e.Message + ")", e);
                }
            }
        }

        /// <summary>Throws ProximaException (VersionMismatch) unless the loaded library's
        /// major version is the binding's (and, before 1.0, its minor too).</summary>
        public static void Check()
        {
            Version lib = Library, bound = Binding;
            if (lib.Major != bound.Major || (bound.Major == 0 && lib.Minor != bound.Minor))
                throw new ProximaException(Result.VersionMismatch,
                    "the native library is Proxima " + lib + " but this binding was written for " + bound +
                    ": use the libproxima built with these bindings");
        }

        public override string ToString() => Major + "." + Minor + "." + Patch;
    }

    /// <summary>A vector: metres for points, newtons for forces, newton-metres for torques.</summary>
    public partial struct Vec3 : IEquatable<Vec3>
    {
        public Vec3(double x, double y, double z) { X = x; Y = y; Z = z; }

        public static readonly Vec3 Zero = new Vec3(0, 0, 0);
        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);
        public static Vec3 operator +(Vec3 a, Vec3 b) => new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vec3 operator -(Vec3 a, Vec3 b) => new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vec3 operator *(double s, Vec3 a) => new Vec3(s * a.X, s * a.Y, s * a.Z);
        public bool Equals(Vec3 o) => X == o.X && Y == o.Y && Z == o.Z;
        public override bool Equals(object obj) => obj is Vec3 v && Equals(v);
        public override int GetHashCode() => X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919);
        public override string ToString() => "(" + X.ToString("R") + ", " + Y.ToString("R") + ", " + Z.ToString("R") + ")";
    }

    /// <summary>A rotation as a unit quaternion (w, x, y, z); normalised by Proxima on input.</summary>
    public partial struct Quat : IEquatable<Quat>
    {
        public Quat(double w, double x, double y, double z) { W = w; X = x; Y = y; Z = z; }

        public static readonly Quat Identity = new Quat(1, 0, 0, 0);

        /// <summary>A rotation of `radians` about `axis` (any length but zero).</summary>
        public static Quat FromAxisAngle(Vec3 axis, double radians)
        {
            double n = axis.Length, s = Math.Sin(0.5 * radians) / n;
            return new Quat(Math.Cos(0.5 * radians), axis.X * s, axis.Y * s, axis.Z * s);
        }

        public bool Equals(Quat o) => W == o.W && X == o.X && Y == o.Y && Z == o.Z;
        public override bool Equals(object obj) => obj is Quat q && Equals(q);
        public override int GetHashCode() => W.GetHashCode() ^ (X.GetHashCode() * 397) ^ (Y.GetHashCode() * 7919) ^ (Z.GetHashCode() * 104729);
        public override string ToString() => "(" + W.ToString("R") + ", " + X.ToString("R") + ", " + Y.ToString("R") + ", " + Z.ToString("R") + ")";
    }

    /// <summary>A rigid pose: world = Rotation * local + Position.</summary>
    public partial struct Pose : IEquatable<Pose>
    {
        public Pose(Vec3 position, Quat rotation) { Position = position; Rotation = rotation; }

        public static readonly Pose Identity = new Pose(Vec3.Zero, Quat.Identity);
        public bool Equals(Pose o) => Position.Equals(o.Position) && Rotation.Equals(o.Rotation);
        public override bool Equals(object obj) => obj is Pose p && Equals(p);
        public override int GetHashCode() => Position.GetHashCode() ^ (Rotation.GetHashCode() * 31);
        public override string ToString() => "{" + Position + ", " + Rotation + "}";
    }

    /// <summary>The virtual coupling of a constrained tool: N/m, N s/m, N m/rad, N m s/rad.</summary>
    public struct Coupling
    {
        public double Stiffness, Damping, AngularStiffness, AngularDamping;
    }

    /// <summary>A closest feature of a triangle.</summary>
    public enum Feature { Vertex = 0, Edge = 1, Face = 2 }

    /// <summary>proxForceSettings: the force curve of every contact.</summary>
    public partial struct ForceSettings
    {
        /// <summary>A preset's force settings and cutoff (metres). Any thread.</summary>
        public static ForceSettings FromPreset(ForcePreset preset, out double cutoff)
        {
            Native.Check(Native.proxGetForcePreset(preset, out ForceSettings force, out cutoff));
            return force;
        }
    }

    /// <summary>proxSkinInfo: one skin of a glTF mesh.</summary>
    public partial struct SkinInfo
    {
        /// <summary>The skin's name in the file; "" when it has none.</summary>
        public string Name => Native.CString(name);
    }

    /// <summary>proxAnimationInfo: one animation of a glTF mesh, times in seconds.</summary>
    public partial struct AnimationInfo
    {
        /// <summary>The animation's name in the file, else "animation N".</summary>
        public string Name => Native.CString(name);
    }

    /// <summary>An intersection polyline: where the tool's surface crosses another body's.</summary>
    public sealed class Polyline
    {
        public Body Other { get; }
        public Vec3[] Points { get; }  // world frame
        public bool Closed { get; }    // the last point joins the first

        public Polyline(Body other, Vec3[] points, bool closed) { Other = other; Points = points; Closed = closed; }
    }

    /// <summary>proxThreadsDef: start from ThreadSettings.Default and change what you need.</summary>
    public partial struct ThreadSettings
    {
        /// <summary>Every field at its default (proxDefaultThreadsDef). Any thread.</summary>
        public static ThreadSettings Default => Native.proxDefaultThreadsDef();
    }
}
