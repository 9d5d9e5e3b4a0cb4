"""The end of the data flow: what the package publishes.

The `appell` command (`cli`), the verification record (`verification`), the
errata (`errata`), and, under this folder, the generated LaTeX appendix.
"""
