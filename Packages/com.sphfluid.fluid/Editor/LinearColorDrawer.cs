using SphFluid.Runtime;
using SphFluid.Simulation;
using UnityEditor;
using UnityEngine;

namespace SphFluid.Editor
{
    /// <summary>
    /// A core colour (<see cref="SettingColor"/>, stored linear as the phase table uses it) as a colour picker in sRGB, as
    /// Unity shows every colour: the stored value is shown through Color.gamma and a pick is stored through Color.linear.
    /// Only a changed pick is written back, so that opening the inspector does not round a stored value.
    /// </summary>
    [CustomPropertyDrawer(typeof(SettingColor))]
    public sealed class LinearColorDrawer : PropertyDrawer
    {
        public override float GetPropertyHeight(SerializedProperty property, GUIContent label) => EditorGUIUtility.singleLineHeight;

        public override void OnGUI(Rect position, SerializedProperty property, GUIContent label)
        {
            SerializedProperty r = property.FindPropertyRelative(nameof(SettingColor.r));
            SerializedProperty g = property.FindPropertyRelative(nameof(SettingColor.g));
            SerializedProperty b = property.FindPropertyRelative(nameof(SettingColor.b));
            SerializedProperty a = property.FindPropertyRelative(nameof(SettingColor.a));
            var stored = new SettingColor(r.floatValue, g.floatValue, b.floatValue, a.floatValue);
            using (new EditorGUI.PropertyScope(position, label, property))
            {
                EditorGUI.BeginChangeCheck();
                Color picked = EditorGUI.ColorField(position, label, stored.ToInspectorColor(), true, true, false);
                if (!EditorGUI.EndChangeCheck()) return;
                SettingColor linear = picked.ToLinearSetting();
                r.floatValue = linear.r;
                g.floatValue = linear.g;
                b.floatValue = linear.b;
                a.floatValue = linear.a;
            }
        }
    }
}
