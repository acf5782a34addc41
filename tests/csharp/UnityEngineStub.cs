// COMPILE CHECK ONLY: a stub of exactly the UnityEngine members that
// bindings/csharp/com.proxima.sdk/Runtime/Unity/ and its sample use, so that
// CI (which has no Unity) compiles them. No member does anything; nothing
// compiled against this stub is ever run. In Unity the real UnityEngine
// replaces it.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public class Object
    {
        public string name { get; set; }
        public static T FindObjectOfType<T>() where T : Object => throw new NotSupportedException("compile check only");
        public static void Destroy(Object obj) => throw new NotSupportedException("compile check only");
    }

    public class Component : Object
    {
        public Transform transform => throw new NotSupportedException("compile check only");
        public T GetComponent<T>() => throw new NotSupportedException("compile check only");
    }

    public class Behaviour : Component { }

    public class MonoBehaviour : Behaviour { }

    public class Transform : Component
    {
        public Vector3 position { get; set; }
        public Quaternion rotation { get; set; }
        public Vector3 lossyScale { get; }
        public bool hasChanged { get; set; }
    }

    public struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 Scale(Vector3 a, Vector3 b) => throw new NotSupportedException("compile check only");
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
    }

    public struct Color
    {
        public static Color yellow => default(Color);
        public static Color red => default(Color);
    }

    public sealed class Mesh : Object
    {
        public Vector3[] vertices { get; set; }
        public int[] triangles { get; set; }
        public void GetVertices(List<Vector3> vertices) => throw new NotSupportedException("compile check only");
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get; set; }
    }

    public class Renderer : Component { }

    public class SkinnedMeshRenderer : Renderer
    {
        public Mesh sharedMesh { get; set; }
        public void BakeMesh(Mesh mesh, bool useScale) => throw new NotSupportedException("compile check only");
    }

    public static class Gizmos
    {
        public static Color color { get; set; }
        public static void DrawLine(Vector3 from, Vector3 to) => throw new NotSupportedException("compile check only");
        public static void DrawSphere(Vector3 center, float radius) => throw new NotSupportedException("compile check only");
    }

    public static class Debug
    {
        public static void Log(object message) => throw new NotSupportedException("compile check only");
        public static void LogWarning(object message) => throw new NotSupportedException("compile check only");
        public static void LogError(object message) => throw new NotSupportedException("compile check only");
    }

    public static class Time
    {
        public static float time => throw new NotSupportedException("compile check only");
    }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponentAttribute : Attribute
    {
        public RequireComponentAttribute(Type type) { }
    }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DisallowMultipleComponentAttribute : Attribute { }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class DefaultExecutionOrderAttribute : Attribute
    {
        public DefaultExecutionOrderAttribute(int order) { }
    }

    [AttributeUsage(AttributeTargets.Class)]
    public sealed class AddComponentMenuAttribute : Attribute
    {
        public AddComponentMenuAttribute(string menuName) { }
    }

    [AttributeUsage(AttributeTargets.Field)]
    public sealed class TooltipAttribute : Attribute
    {
        public TooltipAttribute(string tooltip) { }
    }
}
