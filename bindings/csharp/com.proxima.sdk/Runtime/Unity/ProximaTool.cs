using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>The held tool: a MeshFilter's mesh as a Proxima tool, moved by its
    /// Transform. When the world runs its threads, the Transform's pose goes through
    /// a streamed device, pushed each Update, and the haptic loop renders it at
    /// 1 kHz (interpolated, streamDelay behind); when the world steps, each Update
    /// sets the pose. With a managed Device instead (set before Start, from a
    /// script) the device holds the tool and the Transform follows it. Exposes the
    /// wrench in Unity's frame and draws the contacts with Gizmos.</summary>
    [RequireComponent(typeof(MeshFilter))]
    [AddComponentMenu("Proxima/Proxima Tool")]
    public sealed class ProximaTool : MonoBehaviour
    {
        [Tooltip("The world to join; empty: the scene's ProximaWorld")]
        public ProximaWorld world;
        [Tooltip("How many contacts are read each frame (for Gizmos and ContactCount)")]
        public int maxContacts = 256;
        [Tooltip("Draw each contact's closest points and the line between them")]
        public bool drawContacts = true;
        [Tooltip("With the world's threads: how the haptic loop renders the poses pushed each frame")]
        public StreamMode streamMode = StreamMode.Interpolate;
        [Tooltip("Seconds the rendered pose lags the newest frame's, so that a sample is nearly always on either side: at least one frame")]
        public double streamDelay = 1.0 / 50;

        /// <summary>A managed device that holds the tool instead of its Transform; set before
        /// Start. It is called only while the world runs its threads.</summary>
        public Device Device { get; set; }

        public Body Body => body;
        Body body;

        /// <summary>The streamed device that carries the Transform's pose to the haptic
        /// loop, when the world runs its threads and no Device is set.</summary>
        public StreamDevice? Stream { get; private set; }
        /// <summary>N, on the tool, Unity's frame.</summary>
        public Vector3 Force { get; private set; }
        /// <summary>N m, on the tool about its mesh's bounds centre, Unity's frame.</summary>
        public Vector3 Torque { get; private set; }
        /// <summary>The safety gate or the force clip changed the wrench.</summary>
        public bool Clipped { get; private set; }
        /// <summary>How many contacts the tool has (may exceed maxContacts).</summary>
        public int ContactCount { get; private set; }

        Proxima.Mesh mesh;
        Contact[] contacts;

        void Start()
        {
            world = ProximaWorld.Find(world);
            mesh = UnityFrame.CreateMesh(world.World, GetComponent<MeshFilter>());
            MeshInfo info = mesh.Info;
            Vec3 centre = 0.5 * (info.BoundsMin + info.BoundsMax);
            body = world.World.CreateBody(mesh, BodyType.Tool, UnityFrame.ToProxima(transform), centre);
            if (Device != null)
            {
                body.SetDevice(Device);
            }
            else if (world.runThreads)
            {
                StreamDeviceSettings settings = StreamDeviceSettings.Default;
                settings.Mode = streamMode;
                settings.Delay = streamDelay;
                StreamDevice stream = world.World.CreateStreamDevice(settings);
                body.SetDevice(stream);
                stream.PushPose(UnityFrame.ToProxima(transform));
                Stream = stream;
            }
            contacts = new Contact[System.Math.Max(0, maxContacts)];
        }

        void Update()
        {
            if (Body.IsNull || Device != null) return;
            if (Stream.HasValue)
                Stream.Value.PushPose(UnityFrame.ToProxima(transform));
            else
                body.Pose = UnityFrame.ToProxima(transform);
        }

        void LateUpdate()
        {
            if (Body.IsNull) return;
            if (Device != null)
            {
                Pose p = Body.Pose;
                transform.position = UnityFrame.ToUnity(p.Position);
                transform.rotation = UnityFrame.ToUnity(p.Rotation);
            }
            Wrench w = Body.GetWrench();
            Force = UnityFrame.ToUnity(w.Force);
            Torque = UnityFrame.TorqueToUnity(w.Torque);
            Clipped = w.Clipped;
            ContactCount = Body.GetContacts(contacts);
        }

        void OnDrawGizmos()
        {
            if (!drawContacts || contacts == null) return;
            int n = System.Math.Min(ContactCount, contacts.Length);
            for (int i = 0; i < n; ++i)
            {
                Vector3 a = UnityFrame.ToUnity(contacts[i].PointOther), b = UnityFrame.ToUnity(contacts[i].PointTool);
                Gizmos.color = Color.yellow;
                Gizmos.DrawLine(a, b);
                Gizmos.color = Color.red;
                Gizmos.DrawSphere(a, 0.0005f);
            }
        }

        void OnDestroy()
        {
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
