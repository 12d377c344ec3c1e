"""The tagger's constructions, as ordered tables of named rules (:class:`~seal_cli.language.rule.Rule`).

The tagger (:class:`seal_cli.language.lexicon.Tagger`) tries, at each word, the rules of
``ANYWHERE``; where a clause starts (a verb is expected), those of ``CLAUSE_START``; then those of
``INSIDE``, whose last rule tags the word itself by ``WORDS``. The first rule that consumes words
wins, so the order of each table is the precedence of its constructions. A rule that consumes
nothing (it only retags the last word) lets the next rule of its table try. One file per family
of constructions; each rule carries worked examples, which ``tests/language/test_rules.py`` runs.
"""

from __future__ import annotations

from seal_cli.language.rule import Rule
from seal_cli.language.rules import (
    clauses,
    fronted,
    function_words,
    lead_ins,
    numbers,
    open_words,
    politeness,
    requests,
    statements,
    verbs,
)

__all__ = ["ANYWHERE", "CLAUSE_START", "INSIDE", "TABLES", "WORDS"]

ANYWHERE: tuple[Rule, ...] = (verbs.SPLIT_PARTICLE, politeness.FORMULA)
"""At every word, first."""

CLAUSE_START: tuple[Rule, ...] = (
    requests.PATH_ALONE_RULE,
    politeness.ASKED_AGAIN_RULE,
    politeness.WHILE_HOLDING,
    fronted.FRONTED_WITH,
    politeness.ADVERB_COMMA,
    politeness.POLITENESS,
    politeness.EMPHATIC_DO,
    politeness.YOU_IMPERATIVE,
    lead_ins.COMMA_AFTER_POLITENESS,
    lead_ins.SEQUENCING,
    lead_ins.BEING_AT_RULE,
    lead_ins.HAVING_FIRST_RULE,
    lead_ins.ON_THE_WAY,
    lead_ins.SUBORDINATE,
    lead_ins.MANNER,
    lead_ins.BE_CAREFUL,
    lead_ins.START_BY,
    lead_ins.ASPECT,
    lead_ins.LIGHT_VERB,
    lead_ins.WATCHING_RULE,
    lead_ins.POLITE_FRAME,
    politeness.VOCATIVE_NAME,
    requests.NUMBER_OF_RULE,
    requests.QUESTION,
    requests.FRONTED_QUESTION,
    requests.WHERE,
    requests.WHERE_DID_RULE,
    requests.SEEN_ASKED_RULE,
    requests.ASKED_WHERE,
    requests.STATE_QUESTION,
    requests.LEFT_ASKED_RULE,
    requests.ENSURED_RULE,
    requests.ASKED_WHETHER,
    requests.FOUND_OUT_RULE,
    requests.WHETHER_IS_RULE,
    requests.KNOW_WISH,
    requests.WISHED_PLACED_RULE,
    requests.THING_PLACED,
    requests.WISHED_STATE,
    requests.RESULTATIVE,
    requests.OBLIGED_RULE,
    requests.REQUEST,
    requests.WISH_OF,
    requests.WISH_OF_PHRASE,
    requests.LET_KNOW_RULE,
    requests.FRONTED_OF,
    requests.TOLD_HOW_MANY,
    verbs.SEEN_TO_RULE,
    requests.SWITCHED_ALONE,
    requests.ANY_ASKED,
    requests.ASKED_ALONE_RULE,
    requests.SWITCHED_BY_UNKNOWN,
    verbs.USE,
    verbs.VERB,
    statements.DISLOCATED,
    statements.ASIDE,
)
"""Where a clause starts: what may come before its verb, and the verb. When none matches, the
word is tagged as what it is (``INSIDE``), and the grammar reports the missing verb."""

INSIDE: tuple[Rule, ...] = (
    clauses.END_MARK,
    requests.KNOW_AFTER_LET,
    requests.STATE_ASKED,
    requests.WHETHER_BE,
    requests.REMAINING,
    requests.WHERE_BE_DROPPED,
    requests.ENSURED_STATE,
    requests.WISH_DROPPED,
    requests.OBLIGED_DROPPED,
    clauses.PARTITIVE_OF,
    clauses.PARTICLE_BETWEEN_OBJECTS,
    statements.HER_TOLD,
    statements.TOLD,
    statements.TOLD_HOW_TO,
    requests.HOW_MANY_SEEN,
    requests.HOW_MANY_SAID,
    verbs.MOVED_YOURSELF,
    politeness.PLEASE_INSIDE,
    clauses.SOMETHING_TO,
    verbs.TELL_TO,
    verbs.TOLD_TO_DO,
    clauses.FOR_SUBJECT_TO,
    verbs.PURPOSE,
    clauses.UNTIL_ARRIVAL,
    clauses.UNTIL_PLACE,
    clauses.SUBORDINATE_INSIDE,
    clauses.RELATIVE,
    statements.REMARK_UNMARKED,
    requests.FRONTED_END,
    statements.REMARK_AFTER,
    clauses.COMMA_RELATIVE,
    clauses.VERB_AFTER_JOINT,
    clauses.SEPARATOR,
    politeness.TAG_QUESTION,
    politeness.THANKS,
    clauses.UNJOINED,
    clauses.UNKNOWN_UNJOINED,
)
"""Inside a clause, before the word is tagged by ``WORDS``."""

WORDS: tuple[Rule, ...] = (
    numbers.LABEL,
    numbers.NUMBER_AS_NOUN,
    numbers.COUNT,
    numbers.COUNT_AFTER_ARTICLE,
    numbers.DIGITS,
    numbers.APOSTROPHE_S,
    numbers.QUANTIFIER_OF,
    function_words.PARTICLE_NOUN,
    function_words.ORDINAL_FROM_AN_END,
    function_words.SIDE_OF_REGION,
    function_words.OF,
    function_words.DETERMINER_IN_NP,
    function_words.TIME_WORD,
    function_words.FOR_A_TIME,
    function_words.CLOCK_TIME,
    function_words.ONE,
    function_words.THAT_SAID,
    function_words.OUT_OF_THE_HOUSE,
    function_words.HERE,
    function_words.BACK,
    function_words.PREPOSITION,
    function_words.PARTICLE,
    function_words.WH,
    function_words.BE,
    function_words.POSSESSIVE,
    function_words.PARTITIVE,
    function_words.DETERMINER,
    function_words.WHATEVER,
    function_words.PRONOUN_QUANTIFIED,
    function_words.PRONOUN,
    open_words.FILLED_WITH,
    open_words.KIND_GERUND,
    open_words.PARTICIPLE,
    open_words.RESULT,
    open_words.ADVERB,
    open_words.ADVERB_OF_PLACE,
    open_words.NAME,
    open_words.TITLE_IN_LOWER_CASE,
    open_words.LOWER_CASE_NAME,
    open_words.WORD,
)
"""The word itself: numbers, function words, open-class words; the last always matches."""

TABLES: dict[str, tuple[Rule, ...]] = {"anywhere": ANYWHERE, "clause start": CLAUSE_START, "inside": INSIDE,
                                       "words": WORDS}
