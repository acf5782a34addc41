using System.Collections.Generic;
using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>What a ProximaBody on a SkinnedMeshRenderer does each frame.</summary>
    public enum SkinFeedMode
    {
        /// <summary>The mesh stays as baked at Start.</summary>
        Off,
        /// <summary>Each LateUpdate bakes the skin (SkinnedMeshRenderer.BakeMesh: any skin,
        /// blend shapes included) and feeds its vertices to the Proxima mesh.</summary>
        Bake,
    }

    /// <summary>A MeshFilter's mesh, or a SkinnedMeshRenderer's skin, as a Proxima body,
    /// static or movable, posed by its Transform (see UnityFrame for the frame
    /// conversion). A movable body sends its pose whenever its Transform changed.
    /// A skin is baked at Start in the Transform's frame, its scale applied, and, with
    /// skinFeed Bake, baked again and fed to Proxima every LateUpdate (SkinFeed maps
    /// Unity's seam vertices to Proxima's welded ones). The execution order puts that
    /// feed before ProximaWorld's step, after Unity's animation has posed the skin.</summary>
    [DefaultExecutionOrder(-200)]
    [AddComponentMenu("Proxima/Proxima Body")]
    public sealed class ProximaBody : MonoBehaviour
    {
        [Tooltip("Static bodies never move; movable ones follow their Transform")]
        public bool movable;
        [Tooltip("The world to join; empty: the scene's ProximaWorld")]
        public ProximaWorld world;
        [Tooltip("On a SkinnedMeshRenderer: Bake feeds the posed skin to Proxima every frame; Off keeps the shape of Start")]
        public SkinFeedMode skinFeed = SkinFeedMode.Bake;

        /// <summary>The Proxima body, from Start on.</summary>
        public Body Body => body;
        Body body;
        Proxima.Mesh mesh;

        // The skin's feed and what it reuses every frame.
        SkinnedMeshRenderer skin;
        SkinFeed feed;
        UnityEngine.Mesh baked;
        readonly List<Vector3> bakedVertices = new List<Vector3>();
        float[] vertexBuffer;

        void Start()
        {
            world = ProximaWorld.Find(world);
            skin = GetComponent<SkinnedMeshRenderer>();
            if (skin != null)
            {
                mesh = CreateSkinMesh();
            }
            else
            {
                MeshFilter filter = GetComponent<MeshFilter>();
                if (filter == null)
                    throw new System.InvalidOperationException(name + " has neither a MeshFilter nor a SkinnedMeshRenderer");
                mesh = UnityFrame.CreateMesh(world.World, filter);
            }
            body = world.World.CreateBody(mesh, movable ? BodyType.Movable : BodyType.Static,
                                          UnityFrame.ToProxima(transform));
            transform.hasChanged = false;
        }

        // The skin as posed now, in this Transform's frame with its scale (BakeMesh's
        // useScale; Proxima poses are rigid, as UnityFrame.CreateMesh applies lossyScale).
        Proxima.Mesh CreateSkinMesh()
        {
            UnityEngine.Mesh source = skin.sharedMesh;
            if (source == null) throw new System.ArgumentException(name + "'s SkinnedMeshRenderer has no mesh");
            baked = new UnityEngine.Mesh();
            int count = Bake();
            vertexBuffer = new float[3 * count];
            Copy(count);
            feed = SkinFeed.Create(world.World, vertexBuffer, source.triangles);
            return feed.Mesh;
        }

        // Bakes the skin into the reused mesh and list; returns its vertex count.
        int Bake()
        {
            skin.BakeMesh(baked, true);
            baked.GetVertices(bakedVertices);
            return bakedVertices.Count;
        }

        void Copy(int count)
        {
            for (int i = 0; i < count; ++i)
            {
                Vector3 v = bakedVertices[i];
                vertexBuffer[3 * i] = v.x;
                vertexBuffer[3 * i + 1] = v.y;
                vertexBuffer[3 * i + 2] = v.z;
            }
        }

        void Update()
        {
            if (!movable || Body.IsNull || !transform.hasChanged) return;
            body.Pose = UnityFrame.ToProxima(transform);
            transform.hasChanged = false;
        }

        void LateUpdate()
        {
            if (feed == null || skinFeed != SkinFeedMode.Bake || Body.IsNull || world == null || !world.IsAlive) return;
            int count = Bake();
            Copy(System.Math.Min(count, feed.SourceVertexCount));
            try
            {
                feed.Feed(vertexBuffer, count);
            }
            catch (System.Exception e) when (e is System.ArgumentException || e is ProximaException)
            {
                // A mesh swapped for another, or a pose Proxima refuses: said once, then the
                // body keeps its last shape.
                Debug.LogError(name + ": the skin is no longer fed to Proxima: " + e.Message);
                skinFeed = SkinFeedMode.Off;
            }
        }

        void OnDestroy()
        {
            if (baked != null) Destroy(baked);
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
