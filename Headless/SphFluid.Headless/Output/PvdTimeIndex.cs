using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using System.Xml;

namespace SphFluid.Headless.Output;

/// <summary>
/// The ParaView collection (.pvd) that turns the particle .vtu files into one time series: a VTKFile of type
/// Collection with one DataSet (timestep in s, file name relative to the .pvd) per export. It is rewritten whole
/// after every export, so a run stopped early still leaves a valid index of what it wrote.
/// </summary>
public sealed class PvdTimeIndex
{
    readonly List<(double Time, string File)> _entries = new();

    public IReadOnlyList<(double Time, string File)> Entries => _entries;

    public void Add(double time, string fileName) => _entries.Add((time, fileName));

    public void Write(Stream stream)
    {
        var c = CultureInfo.InvariantCulture;
        using var xml = XmlWriter.Create(stream, new XmlWriterSettings { Indent = true, Encoding = new UTF8Encoding(false), NewLineChars = "\n" });
        xml.WriteStartDocument();
        xml.WriteStartElement("VTKFile");
        xml.WriteAttributeString("type", "Collection");
        xml.WriteAttributeString("version", "0.1");
        xml.WriteAttributeString("byte_order", "LittleEndian");
        xml.WriteStartElement("Collection");
        foreach (var (time, file) in _entries)
        {
            xml.WriteStartElement("DataSet");
            xml.WriteAttributeString("timestep", time.ToString("R", c));
            xml.WriteAttributeString("group", "");
            xml.WriteAttributeString("part", "0");
            xml.WriteAttributeString("file", file);
            xml.WriteEndElement();
        }
        xml.WriteEndElement();
        xml.WriteEndElement();
        xml.WriteEndDocument();
    }
}
