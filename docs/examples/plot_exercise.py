"""
An exam question, marked and solved
===================================

``pixelpath.exercises`` makes the notes' typical exam questions from a seed, marks answers
value by value and writes the worked solution, with figures where the notes would draw one.
"""

from pixelpath import exercises

ex = exercises.make("phong-intensity", seed=7)
print(ex.question)

# %%
# A student's answer, marked: the first wrong value and the step to look at.

result = ex.check({"ambient": 0.05, "diffuse": 0.26, "specular": 0.06, "I": 0.56})
print(result.first_wrong, result.feedback)

# %%
# The worked solution (Markdown), step by step:

print(ex.solution)

# %%
# A Warnock question with its figure, and the solved figure:

warnock = exercises.make("warnock", seed=1)
print(warnock.question)
warnock.figure().save("warnock-question.png")
warnock.figure(solution=True).save("warnock-solved.png")
