using Proxima.Unity;
using UnityEngine;

namespace Proxima.Samples
{
    /// <summary>Logs what the tool feels twice a second: add it beside a ProximaTool.</summary>
    [RequireComponent(typeof(ProximaTool))]
    public sealed class ForceReadout : MonoBehaviour
    {
        ProximaTool tool;
        float next;

        void Start() { tool = GetComponent<ProximaTool>(); }

        void Update()
        {
            if (Time.time < next) return;
            next = Time.time + 0.5f;
            Vector3 f = tool.Force;
            Debug.Log(name + ": " + tool.ContactCount + " contacts, force (" + f.x + ", " + f.y + ", " + f.z + ") N" +
                      (tool.Clipped ? " (clipped)" : ""));
        }
    }
}
