using System.Reflection;
using NUnit.Framework;

namespace SphFluid.Tests.EditMode
{
    /// <summary>Sets a component's private serialized field as the inspector would, without triggering OnValidate.</summary>
    static class SerializedFields
    {
        public static void Set(object component, string field, object value)
        {
            FieldInfo info = component.GetType().GetField(field, BindingFlags.Instance | BindingFlags.NonPublic);
            Assert.That(info, Is.Not.Null, $"{component.GetType().Name} has no serialized field '{field}'");
            info.SetValue(component, value);
        }

        public static void InvokeOnValidate(object component)
        {
            MethodInfo method = component.GetType().GetMethod("OnValidate", BindingFlags.Instance | BindingFlags.NonPublic);
            Assert.That(method, Is.Not.Null, $"{component.GetType().Name} has no OnValidate");
            method.Invoke(component, null);
        }
    }
}
