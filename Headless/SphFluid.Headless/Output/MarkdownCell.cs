namespace SphFluid.Headless.Output;

/// <summary>Text set into a cell of a Markdown table (study.md, summary.txt's phase table): a bar in a phase's name
/// would end its cell and move every later figure under the next column's heading.</summary>
public static class MarkdownCell
{
    public static string Escape(string text) => text.Replace("|", "\\|");
}
