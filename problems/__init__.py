"""The problem bank: documents (schema, loader), per-student variants, compiled questions, self-test.

schema      the document's shape (pydantic)            loader     YAML/JSON in, every fault at once
semantics   meaning checks (expressions, units, ids)   symbols    declarations -> SymbolSpec/Symbol
variants    per-student givens, the student's view     compiled   per-part questions, cached
modelinfo   the one seam to physics.engine             selftest   `physcheck bank verify`
"""
