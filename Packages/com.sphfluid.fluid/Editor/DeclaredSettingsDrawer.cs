using SphFluid.Simulation;
using UnityEditor;
using UnityEngine;

namespace SphFluid.Editor
{
    /// <summary>
    /// Draws a core settings object (<see cref="FluidSettings"/>, a SpawnBox's <see cref="FluidBlock"/> with its
    /// <see cref="PhaseDescription"/> block, the motion laws <see cref="SpinLaw"/> and <see cref="DriveLaw"/>) from its
    /// declarations: a header per group, each field with its tooltip, unit and range, clamped to that range like Unity's
    /// own Range attribute. The core cannot carry Unity's attributes (it is engine-free), so this drawer is how the
    /// inspector reads the one declaration.
    /// </summary>
    [CustomPropertyDrawer(typeof(FluidSettings))]
    [CustomPropertyDrawer(typeof(FluidBlock))]
    [CustomPropertyDrawer(typeof(PhaseDescription))]
    [CustomPropertyDrawer(typeof(SpinLaw))]
    [CustomPropertyDrawer(typeof(DriveLaw))]
    public sealed class DeclaredSettingsDrawer : PropertyDrawer
    {
        static float Line => EditorGUIUtility.singleLineHeight;

        static float Gap => EditorGUIUtility.standardVerticalSpacing;

        public override float GetPropertyHeight(SerializedProperty property, GUIContent label)
        {
            float height = 0f;
            string group = null;
            foreach (SettingPath setting in SettingRules.DeclaredPaths(fieldInfo.FieldType))
            {
                if (setting.Declaration.Group != group)
                {
                    group = setting.Declaration.Group;
                    height += Line + Gap;
                }
                SerializedProperty field = property.FindPropertyRelative(setting.Path);
                if (field != null) height += EditorGUI.GetPropertyHeight(field, GUIContent.none, true) + Gap;
            }
            return height;
        }

        public override void OnGUI(Rect position, SerializedProperty property, GUIContent label)
        {
            var row = new Rect(position.x, position.y, position.width, Line);
            string group = null;
            foreach (SettingPath setting in SettingRules.DeclaredPaths(fieldInfo.FieldType))
            {
                SettingAttribute declaration = setting.Declaration;
                if (declaration.Group != group)
                {
                    group = declaration.Group;
                    row.height = Line;
                    EditorGUI.LabelField(row, group, EditorStyles.boldLabel);
                    row.y += Line + Gap;
                }
                SerializedProperty field = property.FindPropertyRelative(setting.Path);
                if (field == null) continue;
                var content = new GUIContent(ObjectNames.NicifyVariableName(setting.Field.Name),
                    declaration.Tooltip + " Range " + declaration.RangeText + ".");
                row.height = EditorGUI.GetPropertyHeight(field, content, true);
                EditorGUI.PropertyField(row, field, content, true);
                Clamp(field, declaration);
                row.y += row.height + Gap;
            }
        }

        /// <summary>Keeps a typed number inside its declared range; an exclusive minimum is left to the validation,
        /// which names it in the inspector's message.</summary>
        static void Clamp(SerializedProperty field, SettingAttribute declaration)
        {
            if (field.propertyType == SerializedPropertyType.Float)
            {
                float clamped = Mathf.Clamp(field.floatValue, (float)declaration.Min, (float)declaration.Max);
                if (clamped != field.floatValue) field.floatValue = clamped;
            }
            else if (field.propertyType == SerializedPropertyType.Integer)
            {
                int clamped = Mathf.Clamp(field.intValue, (int)declaration.Min, (int)declaration.Max);
                if (clamped != field.intValue) field.intValue = clamped;
            }
        }
    }
}
