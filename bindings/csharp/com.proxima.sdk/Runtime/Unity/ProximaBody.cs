using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>A MeshFilter's mesh as a Proxima body, static or movable, posed by its
    /// Transform (see UnityFrame for the frame conversion). A movable body sends
    /// its pose whenever its Transform changed.</summary>
    [RequireComponent(typeof(MeshFilter))]
    [AddComponentMenu("Proxima/Proxima Body")]
    public sealed class ProximaBody : MonoBehaviour
    {
        [Tooltip("Static bodies never move; movable ones follow their Transform")]
        public bool movable;
        [Tooltip("The world to join; empty: the scene's ProximaWorld")]
        public ProximaWorld world;

        /// <summary>The Proxima body, from Start on.</summary>
        public Body Body => body;
        Body body;
        Proxima.Mesh mesh;

        void Start()
        {
            world = ProximaWorld.Find(world);
            mesh = UnityFrame.CreateMesh(world.World, GetComponent<MeshFilter>());
            body = world.World.CreateBody(mesh, movable ? BodyType.Movable : BodyType.Static,
                                          UnityFrame.ToProxima(transform));
            transform.hasChanged = false;
        }

        void Update()
        {
            if (!movable || Body.IsNull || !transform.hasChanged) return;
            body.Pose = UnityFrame.ToProxima(transform);
            transform.hasChanged = false;
        }

        void OnDestroy()
        {
            // A world that went first has destroyed the body already; one whose
            // threads run will destroy it with itself.
            if (Body.IsNull || world == null || !world.AcceptsChanges) return;
            try
            {
                Body.Destroy();
                mesh.Destroy();
            }
            catch (ProximaException e)
            {
                Debug.LogWarning(name + ": " + e.Message);
            }
        }
    }
}
