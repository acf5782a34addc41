using Proxima;
using UnityEngine;

namespace Proxima.Unity
{
    /// <summary>The scene's Proxima world. Stepped: one deterministic step per frame
    /// in LateUpdate, after the bodies and tools have sent their poses in Update.
    /// Threaded: the haptic loop (1 kHz), local tracking and the global search run
    /// on Proxima's threads from the first LateUpdate on; bodies and tools may
    /// come and go, and meshes deform, while they run (docs/dynamic-scenes.md).</summary>
    [DisallowMultipleComponent]
    [DefaultExecutionOrder(-100)]
    [AddComponentMenu("Proxima/Proxima World")]
    public sealed class ProximaWorld : MonoBehaviour
    {
        [Tooltip("Precise (the improved method), Original (the Johnson-Cohen baseline) or Reference (brute force)")]
        public Method method = Method.Precise;
        [Tooltip("The force curve: Hard (exponential, 5 mm cutoff) or Soft (linear, 10 mm)")]
        public ForcePreset force = ForcePreset.Hard;
        [Tooltip("Metres; 0: the preset's cutoff")]
        public double cutoff;
        [Tooltip("Run Proxima's threads instead of stepping once per frame")]
        public bool runThreads;

        World world;
        bool started;

        /// <summary>The world, created in Awake; on the main thread only.</summary>
        public World World
        {
            get
            {
                if (world == null)
                    world = new World(new WorldSettings { Method = method, Force = force,
                                                          Cutoff = cutoff > 0 ? cutoff : double.NaN });
                return world;
            }
        }

        /// <summary>The world a body or tool joins: the given one, else the scene's.</summary>
        internal static ProximaWorld Find(ProximaWorld given)
        {
            if (given != null) return given;
            ProximaWorld found = FindObjectOfType<ProximaWorld>();
            if (found == null) throw new System.InvalidOperationException("the scene has no ProximaWorld");
            return found;
        }

        /// <summary>The world exists (meshes may deform, also while its threads run).</summary>
        internal bool IsAlive => world != null && world.IsValid;

        /// <summary>The world exists and its threads do not run: bodies may leave it.</summary>
        internal bool AcceptsChanges => world != null && world.IsValid && !started;

        void Awake() { _ = World; }

        void LateUpdate()
        {
            if (!runThreads)
            {
                World.Step();
                return;
            }
            if (!started)
            {
                World.StartThreads(ThreadSettings.Default);
                started = true;
            }
        }

        void OnDestroy()
        {
            if (world == null) return;
            world.Dispose();
            world = null;
        }
    }
}
